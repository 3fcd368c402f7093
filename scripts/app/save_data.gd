extends RefCounted
## The player's best results per board: fastest maze time in each mode (easy, hard), most
## pachinko balls won.
## Kept in a readable INI file (user://save.cfg); a damaged file is reported and the
## records start empty rather than stopping the game.

const IniText := preload("res://scripts/app/ini_text.gd")
## Version 2 keeps a maze time per mode; version 1 had one time per board, read as easy.
const VERSION := 2
const MAZE_SECTIONS := {false: "maze_best_seconds_easy", true: "maze_best_seconds_hard"}
## The version 1 section: every time in it was an easy-mode time.
const LEGACY_MAZE_SECTION := "maze_best_seconds"
const HEADER := "Board Studio best results (format version %d), per board id."

## hard (bool) -> {board id: seconds}
var _maze_times := {false: {}, true: {}}
var _pachinko_balls := {}
var _path := ""


## Loads the records from `path` and remembers it for saving. Returns "" or the problem.
func load_file(path: String) -> String:
	_path = path
	_maze_times = {false: {}, true: {}}
	_pachinko_balls = {}
	var read := IniText.read_file(path)
	if read.has("missing"):
		return ""
	if read.has("error"):
		return (
			"The best results file %s is damaged (%s); starting a fresh one."
			% [path, read["error"]]
		)
	var sections: Dictionary = read["sections"]
	var meta: Dictionary = sections.get("meta", {})
	var version: Variant = meta.get("version")
	var is_number := version is float or version is int
	var whole: int = version if is_number else 0
	if not is_number or whole < 1 or whole > VERSION:
		return (
			"The best results file %s has an unknown version (%s); starting a fresh one."
			% [path, str(version)]
		)
	if whole == 1:
		_read_maze_times(sections.get(LEGACY_MAZE_SECTION, {}), false)
	else:
		for hard: bool in MAZE_SECTIONS:
			_read_maze_times(sections.get(MAZE_SECTIONS[hard], {}), hard)
	var pachinko: Dictionary = sections.get("pachinko_best_balls", {})
	for board_id: String in pachinko:
		var balls: Variant = pachinko[board_id]
		if (balls is float or balls is int) and balls >= 0:
			var count: int = balls
			_pachinko_balls[board_id] = count
	return ""


## Fastest time on a maze board in one mode (`hard` or easy) in seconds, or -1 when there is
## none yet.
func best_maze_time(board_id: String, hard: bool) -> float:
	var times: Dictionary = _maze_times[hard]
	var time: float = times.get(board_id, -1.0)
	return time


## Records a finished maze run in one mode; true (and saved) when it beats that mode's best.
func record_maze_time(board_id: String, hard: bool, seconds: float) -> bool:
	if board_id.is_empty() or not is_finite(seconds) or seconds <= 0.0:
		push_error(
			(
				"record_maze_time: needs a board id and a positive time, got '%s', %s"
				% [board_id, seconds]
			)
		)
		return false
	var best := best_maze_time(board_id, hard)
	if best > 0.0 and seconds >= best:
		return false
	var times: Dictionary = _maze_times[hard]
	times[board_id] = seconds
	save()
	return true


## Most balls won in one pachinko game on a board, or -1 when there is none yet.
func best_pachinko_balls(board_id: String) -> int:
	var count: int = _pachinko_balls.get(board_id, -1)
	return count


## Records a finished pachinko game; true (and saved) when it won more balls than before.
func record_pachinko_balls(board_id: String, balls: int) -> bool:
	if board_id.is_empty() or balls < 0:
		push_error(
			(
				"record_pachinko_balls: needs a board id and balls >= 0, got '%s', %d"
				% [board_id, balls]
			)
		)
		return false
	if balls <= best_pachinko_balls(board_id):
		return false
	_pachinko_balls[board_id] = balls
	save()
	return true


## Writes the records to the file they were loaded from (nothing when never loaded).
func save() -> Error:
	if _path.is_empty():
		return OK
	var sections := [
		["meta", {"version": VERSION}],
		[MAZE_SECTIONS[false], _maze_times[false]],
		[MAZE_SECTIONS[true], _maze_times[true]],
		["pachinko_best_balls", _pachinko_balls],
	]
	var error := IniText.write_file(_path, IniText.format(HEADER % VERSION, sections))
	if error != OK:
		push_error("Could not save best results to %s: %s" % [_path, error_string(error)])
	return error


func _read_maze_times(section: Dictionary, hard: bool) -> void:
	var times: Dictionary = _maze_times[hard]
	for board_id: String in section:
		var seconds: Variant = section[board_id]
		if not (seconds is float or seconds is int):
			continue
		var time: float = seconds
		if is_finite(time) and time > 0:
			times[board_id] = time
