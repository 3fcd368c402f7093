@tool
extends RefCounted
## The editor's play-test: saves the board, leaves a request the game reads on start
## (App.current_board_path), and runs the board's game scene from the editor.

const PlaytestRequest := preload("res://scripts/app/playtest_request.gd")
const REQUEST_PATH := PlaytestRequest.PATH
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
	EditorInterface.play_custom_scene(scene)
	return ""
