class_name ReplayCli
extends RefCounted
## The `--replay=FILE` command: reads a replay, finds its board by id and content hash,
## plays it headless through the same rules and prints one JSON line:
## {"replay", "game", "board", "steps", "state_hash", "recorded_hash", "match"}.
## Exit 0 when the final state hash matches the recorded one, 1 when it does not, 2 for a
## file that cannot be read or a board that is missing or changed.

const EXIT_MATCH := 0
const EXIT_MISMATCH := 1
const EXIT_BAD_INPUT := 2


## Runs the command for the parsed flags `values` (key "replay": the file path).
static func run(values: Dictionary) -> int:
	var path := str(values["replay"])
	var read := ReplayStore.read_file(path)
	if read.has("error"):
		return _refuse(path, str(read["error"]))
	var replay: Replay = read["replay"]
	var physics := replay.physics_problem()
	if not physics.is_empty():
		return _refuse(path, "%s: cannot be replayed: %s" % [path, physics])
	var board := ReplayStore.find_board(replay)
	if board.has("error"):
		return _refuse(path, "%s: %s" % [path, board["error"]])
	var level: BoardLevel = board["level"]
	var player := ReplayPlayer.new(replay, level)
	var result := player.play_to_end()
	var report := {
		"replay": path,
		"game": replay.game,
		"board": replay.board_id,
		"mode": replay.mode_name(),
		"steps": result["steps"],
		"recorded_steps": result["recorded_steps"],
		"state_hash": result["state_hash"],
		"recorded_hash": result["recorded_hash"],
		"match": result["match"],
	}
	if result.has("diverged"):
		report["diverged"] = result["diverged"]
	print(JSON.stringify(report))
	return EXIT_MATCH if result["match"] else EXIT_MISMATCH


static func _refuse(path: String, problem: String) -> int:
	printerr("replay: %s" % problem)
	print(JSON.stringify({"replay": path, "ok": false, "error": problem}))
	return EXIT_BAD_INPUT


## Records the autoplay's game for `--record=FILE`: a recorder to hand the autoplay, or null
## when the flag is absent.
static func recorder_for(values: Dictionary) -> ReplayRecorder:
	return ReplayRecorder.new() if values.has("record") else null


## Saves what `recorder` recorded to the `--record` file. Returns "" or the problem.
static func save_recording(recorder: ReplayRecorder, values: Dictionary) -> String:
	var path := str(values["record"])
	var replay := recorder.finish()
	if replay == null:
		return "nothing was recorded"
	var error := ReplayStore.save(replay, path)
	if error != OK:
		return "%s: could not write the replay (%s)" % [path, error_string(error)]
	return ""
