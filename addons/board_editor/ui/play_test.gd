@tool
extends RefCounted
## The editor's play-test: saves the board, leaves a request the game reads on start
## (App.current_board_path), and runs the board's game scene from the editor.

const REQUEST_PATH := PlaytestRequest.PATH
## Godot's editor setting "save all scenes before running".
const SAVE_BEFORE_RUNNING := "run/auto_save/save_before_running"
const GAME_SCENES := {
	BoardLevel.PACHINKO_NAME: "res://scenes/pachinko/pachinko_game.tscn",
	BoardLevel.MAZE_NAME: "res://scenes/maze/maze_game.tscn",
}


## Writes the request file for `level`; returns "" or a sentence saying what went wrong.
static func write_request(level: BoardLevel) -> String:
	if level == null:
		return "Play-test: there is no board to play."
	var path := level.resource_path
	if path.is_empty() or path.contains("::"):
		return "Play-test: save the board as its own .board file first (it is built into the scene)."
	var error := ResourceSaver.save(level, path)
	if error != OK:
		return "Play-test: could not save %s (%s)." % [path, error_string(error)]
	return PlaytestRequest.write(path, BoardLevel.kind_name(level.kind))


## Saves, writes the request and plays the board's game; "" or what went wrong.
static func run(level: BoardLevel) -> String:
	var errors := BoardValidator.errors(level).size() if level != null else 0
	if errors > 0:
		var plural := "" if errors == 1 else "s"
		return "Play-test: fix the board's %d error%s first (see Problems)." % [errors, plural]
	var problem := write_request(level)
	if not problem.is_empty():
		return problem
	var scene: String = GAME_SCENES[BoardLevel.kind_name(level.kind)]
	if not ResourceLoader.exists(scene):
		return "Play-test: the game scene %s is missing." % scene
	_play_without_saving_scenes(scene)
	return ""


# The game reads the board file (saved above), never the open scenes. Godot saves every open
# scene before it runs one, and a scene that was never saved opens its "Save Scene As"
# dialog, modal, behind the game window: the editor looks frozen. So the play-test runs with
# that setting off for this one run, then puts it back.
static func _play_without_saving_scenes(scene: String) -> void:
	var settings := EditorInterface.get_editor_settings()
	var had := settings.has_setting(SAVE_BEFORE_RUNNING)
	var before: Variant = settings.get_setting(SAVE_BEFORE_RUNNING) if had else null
	if had:
		settings.set_setting(SAVE_BEFORE_RUNNING, false)
	EditorInterface.play_custom_scene(scene)
	if had:
		settings.set_setting(SAVE_BEFORE_RUNNING, before)
