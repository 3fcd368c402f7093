extends SceneTree
## Converts boards saved in the old text-resource layout (.tres) to `.board` files:
##   tools/godot.sh --headless --path . -s tools/convert_boards.gd -- [FILE.tres ...]
## With no files it converts every .tres board in levels/. Each board is read through the
## old checked path (BoardLoader's legacy branch, which hands the file to Godot's resource
## parser: convert only files you trust), validated, written as FILE.board beside it and read
## back through the data-only reader; only then is the .tres removed (--keep keeps it) and
## every level scene that referred to it pointed at the new file.

const LegacyBoardLoader := preload("res://tools/legacy_boards/legacy_board_loader.gd")
const SCENES_DIR := "res://scenes/boards"


func _initialize() -> void:
	var args := Array(OS.get_cmdline_user_args())
	var keep := args.has("--keep")
	args.erase("--keep")
	var paths: Array[String] = []
	for arg: String in args:
		paths.append(arg if arg.begins_with("res://") else ProjectSettings.localize_path(arg))
	if paths.is_empty():
		paths = _legacy_boards()
	var failed := 0
	for path in paths:
		var problem := convert_board(path, keep)
		print("%s: %s" % [path, "converted" if problem.is_empty() else problem])
		failed += 0 if problem.is_empty() else 1
	print("%d converted, %d failed" % [paths.size() - failed, failed])
	quit(1 if failed > 0 else 0)


## Converts one .tres board; "" or what went wrong (nothing is removed on failure).
static func convert_board(path: String, keep: bool) -> String:
	var loaded := LegacyBoardLoader.load_board(path)
	if not loaded.ok():
		return loaded.error
	var text := BoardTextWriter.write(loaded.level)
	var check := BoardTextReader.read(text)
	if check.has("error"):
		return "the converted board does not read back: %s" % check["error"]
	var target := path.get_basename() + ".board"
	var file := FileAccess.open(target, FileAccess.WRITE)
	if file == null:
		return "could not write %s" % target
	file.store_string(text)
	file.close()
	_repoint_scenes(path, target)
	if not keep:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(path))
		DirAccess.remove_absolute(ProjectSettings.globalize_path(path + ".uid"))
	return ""


static func _legacy_boards() -> Array[String]:
	var found: Array[String] = []
	for kind in BoardLevel.KIND_NAMES:
		var dir := "res://levels/%s" % kind
		for file_name in DirAccess.get_files_at(dir):
			if file_name.ends_with(".tres"):
				found.append("%s/%s" % [dir, file_name])
	return found


static func _repoint_scenes(old_path: String, new_path: String) -> void:
	for file_name in DirAccess.get_files_at(SCENES_DIR):
		if not file_name.ends_with(".tscn"):
			continue
		var scene := "%s/%s" % [SCENES_DIR, file_name]
		var text := FileAccess.get_file_as_string(scene)
		if not text.contains('"%s"' % old_path):
			continue
		var file := FileAccess.open(scene, FileAccess.WRITE)
		file.store_string(text.replace('"%s"' % old_path, '"%s"' % new_path))
		file.close()
