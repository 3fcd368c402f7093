class_name AutoplayCli
extends RefCounted
## The `--autoplay` command: plays one game headless on a board and prints one JSON line
## with what happened. command_line.gd hands it the parsed flags (cli_flags.gd).

## Seconds a game plays when --seconds is not given, in BoardLevel.Kind order.
const DEFAULT_SECONDS: Array[float] = [60.0, 120.0]
## A board that cannot be loaded is bad input, like a bad flag (cli_flags.gd EXIT_USAGE).
const EXIT_BAD_BOARD := 2


## Runs the autoplay `values` ask for (keys autoplay, board, seconds, seed, hard, handle,
## chase; seconds, chase and record may be absent); prints one JSON line; returns the exit
## code: 0 when the game was played, EXIT_BAD_BOARD when it could not be ("ok": false and
## the problem).
static func run(values: Dictionary) -> int:
	var report := play(values)
	if not report["ok"]:
		printerr("autoplay: %s" % report["error"])
	print(JSON.stringify(report))
	return 0 if report["ok"] else EXIT_BAD_BOARD


## The report `run` prints: {"ok": true, "game", "board", "seed", ...what the game said}, or
## {"ok": false, "error"} when the board does not load, is the other game's, or the game
## refused to start.
static func play(values: Dictionary) -> Dictionary:
	var game: String = values["autoplay"]
	var kind := BoardLevel.kind_named(game)
	var seconds: float = values.get("seconds", DEFAULT_SECONDS[kind])
	var board_path := resolve_board_path(game, str(values["board"]))
	var loaded := BoardLoader.load_board(board_path)
	if loaded.level == null:
		return {"ok": false, "error": loaded.error}
	if loaded.level.kind != kind:
		var its_game := BoardLevel.kind_name(loaded.level.kind)
		return {
			"ok": false, "error": "%s: a %s board, not a %s board" % [board_path, its_game, game]
		}
	var result: Dictionary
	var recorder := ReplayCli.recorder_for(values)
	var rng_seed: int = values["seed"]
	if kind == BoardLevel.Kind.MAZE:
		var hard: bool = values["hard"]
		result = MazeAutoplay.run(loaded.level, seconds, rng_seed, hard, recorder)
	else:
		var handle: int = values["handle"]
		var chase: bool = values.get("chase", false)  # the gold-pin chaser only when asked
		result = PachinkoAutoplay.run(loaded.level, seconds, rng_seed, recorder, handle, chase)
	if not result.get("ok", true):
		return {"ok": false, "error": str(result.get("error", "the game did not start"))}
	var report := {"ok": true, "game": game, "board": loaded.level.board_id, "seed": values["seed"]}
	report.merge(result)
	if recorder != null:
		var problem := ReplayCli.save_recording(recorder, values)
		if not problem.is_empty():
			return {"ok": false, "error": problem}
		report["replay"] = values["record"]
	return report


## A bare board name means levels/<game>/<name>.board; a res:// path is used as it is.
static func resolve_board_path(game: String, board: String) -> String:
	if board.begins_with("res://") or board.begins_with("user://"):
		return board
	return "res://levels/%s/%s.board" % [game, board]
