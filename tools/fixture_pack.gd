extends SceneTree
## Packs the test fixtures that Godot's export leaves out (folders marked .gdignore, so the
## editor never imports a hostile file) into one .pck for the release test run:
##   godot --headless --path . -s tools/fixture_pack.gd -- <out.pck>
## The test pack's first scene (tests/release/release_test_main.gd) loads it from beside
## the test binary, so the files read at the same res:// paths as in the editor build.

## The fixture folders that carry a .gdignore (checked: a folder without one is exported).
const FOLDERS: PackedStringArray = [
	"res://tests/fixtures/boards",
	"res://tests/fixtures/hostile_boards",
	"res://tests/fixtures/hostile_user_files",
]


func _init() -> void:
	var args := OS.get_cmdline_user_args()
	if args.size() != 1 or not args[0].ends_with(".pck"):
		printerr("fixture_pack: give the .pck to write after --, e.g. -- build/fixtures.pck")
		quit(2)
		return
	var packer := PCKPacker.new()
	if packer.pck_start(args[0]) != OK:
		printerr("fixture_pack: cannot write %s" % args[0])
		quit(1)
		return
	var count := 0
	for folder in FOLDERS:
		if not FileAccess.file_exists(folder.path_join(".gdignore")):
			printerr("fixture_pack: %s has no .gdignore: the export packs it already" % folder)
			quit(1)
			return
		count += _add_folder(packer, folder)
	if packer.flush() != OK:
		printerr("fixture_pack: could not finish %s" % args[0])
		quit(1)
		return
	print("fixture_pack: %d files in %s" % [count, args[0]])
	quit(0)


# Adds every file under `folder` (sub-folders too, .gdignore itself left out); the count.
func _add_folder(packer: PCKPacker, folder: String) -> int:
	var count := 0
	for name in DirAccess.get_files_at(folder):
		if name == ".gdignore":
			continue
		var path := folder.path_join(name)
		if packer.add_file(path, ProjectSettings.globalize_path(path)) != OK:
			printerr("fixture_pack: could not add %s" % path)
			continue
		count += 1
	for sub in DirAccess.get_directories_at(folder):
		count += _add_folder(packer, folder.path_join(sub))
	return count
