extends SceneTree
## Writes a level scene (scenes/boards/<kind>_<name>.tscn, a BoardNode showing the level)
## for every shipped board that has none, so a designer can open any board in the editor:
##   tools/godot.sh --headless --path . -s tools/make_board_scenes.gd

const SCENES_DIR := "res://scenes/boards"


func _initialize() -> void:
	var failed := false
	for kind: int in [BoardLevel.Kind.PACHINKO, BoardLevel.Kind.MAZE]:
		for loaded in BoardLoader.list_boards(kind):
			var scene_path := scene_path_for(loaded.path)
			if FileAccess.file_exists(scene_path):
				continue
			if not loaded.ok():
				push_warning("make_board_scenes: skipping %s" % loaded.error)
				continue
			failed = not _write(loaded.level, scene_path) or failed
	quit(1 if failed else 0)


## The level scene for the board file at `level_path`.
static func scene_path_for(level_path: String) -> String:
	var kind_name := level_path.get_base_dir().get_file()
	return "%s/%s_%s.tscn" % [SCENES_DIR, kind_name, level_path.get_file().get_basename()]


static func _write(level: BoardLevel, scene_path: String) -> bool:
	var node := BoardNode.new()
	node.name = "Board"
	node.level = level
	var scene := PackedScene.new()
	var error := scene.pack(node)
	if error == OK:
		error = ResourceSaver.save(scene, scene_path)
	node.free()
	if error != OK:
		push_error("make_board_scenes: could not write %s (%s)" % [scene_path, error_string(error)])
		return false
	print("wrote %s" % scene_path)
	return true
