extends RefCounted
## The player's best results per board: fastest maze time, most pachinko balls won.
## Kept in a readable INI file (user://save.cfg); a damaged file is reported and the
## records start empty rather than stopping the game.

const IniText := preload("res://scripts/app/ini_text.gd")
const VERSION := 1
const HEADER := "Board Studio best results (format version %d), per board id."

var _maze_times := {}
var _pachinko_balls := {}
var _path := ""


## Loads the records from `path` and remembers it for saving. Returns "" or the problem.
func load_file(path: String) -> String:
	_path = path
	_maze_times = {}
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
	if not is_number or whole != VERSION:
		return (
			"The best results file %s has an unknown version (%s); starting a fresh one."
			% [path, str(version)]
		)
	var maze: Dictionary = sections.get("maze_best_seconds", {})
	for board_id: String in maze:
		var seconds: Variant = maze[board_id]
		if not (seconds is float or seconds is int):
			continue
		var time: float = seconds
		if is_finite(time) and time > 0:
			_maze_times[board_id] = time
	var pachinko: Dictionary = sections.get("pachinko_best_balls", {})
	for board_id: String in pachinko:
		var balls: Variant = pachinko[board_id]
		if (balls is float or balls is int) and balls >= 0:
			var count: int = balls
			_pachinko_balls[board_id] = count
	return ""


## Fastest time on a maze board in seconds, or -1 when there is none yet.
func best_maze_time(board_id: String) -> float:
	var time: float = _maze_times.get(board_id, -1.0)
	return time


## Records a finished maze run; true (and saved) when it beats the best time.
func record_maze_time(board_id: String, seconds: float) -> bool:
	if board_id.is_empty() or not is_finite(seconds) or seconds <= 0.0:
		push_error(
			(
				"record_maze_time: needs a board id and a positive time, got '%s', %s"
				% [board_id, seconds]
			)
		)
		return false
	var best := best_maze_time(board_id)
	if best > 0.0 and seconds >= best:
		return false
	_maze_times[board_id] = seconds
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
		["maze_best_seconds", _maze_times],
		["pachinko_best_balls", _pachinko_balls],
	]
	var error := IniText.write_file(_path, IniText.format(HEADER % VERSION, sections))
	if error != OK:
		push_error("Could not save best results to %s: %s" % [_path, error_string(error)])
	return error
