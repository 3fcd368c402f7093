extends SceneTree
## Loads every GDScript under scenes/, scripts/, addons/board_editor and tools/ (so a tool
## script that no longer parses is found too) so that a run with
## the debugger on (-d) prints each script's GDScript warnings; tools/warnings_check.sh
## reads them from stderr:
##   tools/godot.sh --headless -d --path . -s res://tools/load_all_scripts.gd
## Godot keeps warnings off under res://addons by default: this turns them on for
## addons/board_editor (not addons/gut) at run time, so project.godot is never touched.
## The engine takes the new rules when settings_changed fires (deferred), so the scripts
## load from that signal. Prints "LOADED n" and exits 0, or 1 when a script failed to load.

const ROOTS: PackedStringArray = [
	"res://scenes", "res://scripts", "res://addons/board_editor", "res://tools"
]
const RULES_SETTING := "debug/gdscript/warnings/directory_rules"
const MAX_FRAMES := 120

var _loaded: int = 0
var _failed: int = 0
var _frames: int = 0


func _initialize() -> void:
	# tools/ is loaded only to find a script that no longer parses (a tool's hook broke that
	# way once, unseen): its warnings are not counted.
	var rules: Dictionary = {"res://addons": 0, "res://addons/board_editor": 1, "res://tools": 0}
	ProjectSettings.settings_changed.connect(_load_all, CONNECT_ONE_SHOT)
	ProjectSettings.set_setting(RULES_SETTING, rules)


func _process(_delta: float) -> bool:
	_frames += 1
	if _frames > MAX_FRAMES:
		printerr("LOADFAIL settings_changed never came: nothing loaded")
		quit(1)
	return false


func _load_all() -> void:
	for top: String in ROOTS:
		_walk(top)
	print("LOADED %d" % _loaded)
	quit(1 if _failed > 0 else 0)


func _walk(dir_path: String) -> void:
	for file: String in DirAccess.get_files_at(dir_path):
		if not file.ends_with(".gd"):
			continue
		var path: String = dir_path.path_join(file)
		if load(path) == null:
			printerr("LOADFAIL " + path)
			_failed += 1
		else:
			_loaded += 1
	for sub: String in DirAccess.get_directories_at(dir_path):
		_walk(dir_path.path_join(sub))
