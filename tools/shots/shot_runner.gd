extends SceneTree
## Renders the game's screens to build/shots/*.png (make shots): the menus, pachinko and the
## tilt maze, in that order. Needs a real window: tools/shots.sh runs it under Xvfb with the
## GL Compatibility renderer. Each shot file opens its screen the way the player gets there,
## puts it in the moment worth showing through public API and input actions only, and saves
## the window with shot_capture.gd (the editor's shots use the same capture).
##   SHOTS_ONLY=maze  only the shots whose names start with "maze"

## The shot files, in the order they run. Loaded once the App autoload exists: they call
## it, and a script given with -s is compiled before the autoloads are there.
const SHOT_FILES: Array[String] = [
	"res://tools/shots/menu_shots.gd",
	"res://tools/shots/pachinko_shots.gd",
	"res://tools/shots/bonus_shots.gd",
	"res://tools/shots/juice_shots.gd",
	"res://tools/shots/machine_shots.gd",
	"res://tools/shots/gold_shots.gd",
	"res://tools/shots/flash_shots.gd",
	"res://tools/shots/maze_shots.gd",
]
## Pictures must never touch the player's own settings and best results; the scratch files
## start empty each run so every run shows the default settings.
const SCRATCH_SETTINGS := "user://shots_settings.cfg"
const SCRATCH_SAVE := "user://shots_save.cfg"


func _initialize() -> void:
	_run.call_deferred()


func _run() -> void:
	for scratch in [SCRATCH_SETTINGS, SCRATCH_SAVE]:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(scratch))
	root.get_node("/root/App").call("load_player_files", SCRATCH_SETTINGS, SCRATCH_SAVE)
	var only := OS.get_environment("SHOTS_ONLY")
	var failed := PackedStringArray()
	var taken := 0
	for path in SHOT_FILES:
		var shots: GDScript = load(path)
		var names: Array[String] = shots.get_script_constant_map()["NAMES"]
		for shot_name in names:
			if not only.is_empty() and not shot_name.begins_with(only):
				continue
			var error: Error = await shots.call("take", self, shot_name)
			taken += 1
			if error != OK:
				failed.append("%s (%s)" % [shot_name, error_string(error)])
	if taken == 0:
		printerr("shots: no shot name starts with SHOTS_ONLY='%s'" % only)
		quit(1)
		return
	if not failed.is_empty():
		printerr("shots: %d of %d failed: %s" % [failed.size(), taken, ", ".join(failed)])
	quit(0 if failed.is_empty() else 1)
