class_name SaveData
extends RefCounted
## The player's best results per board: fastest maze time in each mode (easy, hard), most
## pachinko balls won; the pachinko boards whose full rules card the player has read and
## those whose goal (PachinkoGoals) they reached, and those where the house's first jackpot
## was given (HouseJackpot); and the pachinko handle's strength, kept across boards and
## games.
## Kept in a readable INI file (user://save.cfg), read as data: a board id of any text
## round-trips, an unusable record is dropped on its own, a damaged file is moved aside
## (kept for the player) and the records start empty, a file from a newer version is left
## untouched and never saved over. None of it stops the game.

## Version 2 keeps a maze time per mode; version 1 had one time per board, read as easy.
const VERSION := 2
const MAZE_SECTIONS := {false: "maze_best_seconds_easy", true: "maze_best_seconds_hard"}
## The version 1 section: every time in it was an easy-mode time.
const LEGACY_MAZE_SECTION := "maze_best_seconds"
## Records past this in the message are only counted.
const MAX_LISTED := 5
## A pachinko count past this is not a game anyone played.
const MAX_BALLS := 1_000_000_000

## The best result of one pachinko game, per board: balls ended with less balls started
## (PachinkoGameRecord; before trial 8 it was the game's highest point).
const MOST_WON_SECTION := "pachinko_most_won"
## Before the best was the most balls won it was the most balls PAID BACK, kept here: read
## and written back untouched (the player's record is never deleted), never shown as "Most won".
const PAID_BACK_SECTION := "pachinko_best_balls"

const HEADER := "Board Studio best results (format version %d), per board id."
## What the player is told about a best-results file that could not be used (PlayerFileLoad).
const LOAD_WORDS := {
	"damaged": "The best results in %s could not be read (%s), so they start empty.",
	"newer":
	(
		"%s is from a newer version of Board Studio (format %d): it is left as it is, "
		+ "and this run's best results are not saved."
	),
	"partly": "Some best results in %s could not be used and are left out: %s.",
}

## hard (bool) -> {board id: seconds}
var _maze_times := {false: {}, true: {}}
var _pachinko_balls := {}
# board id -> the most balls paid back, from before "Most won": kept, never shown
var _paid_back_kept := {}
# board id -> true: the pachinko boards whose full rules card the player has played past
var _rules_seen := {}
# board id -> true: the pachinko machines whose goal (PachinkoGoals) the player reached
var _cleared := {}
# board id -> true: the reel machines where the house's first jackpot has landed
var _house_given := {}
# the pachinko handle's strength as the player left it (-1: never turned)
var _handle_power := -1.0
var _path := ""
# a damaged file that could not be moved aside, or one from a newer version: never written
var _untouchable := false


## Loads the records from `path` and remembers it for saving. Returns "" or a sentence for
## the player naming the problem and where the old file went.
func load_file(path: String) -> String:
	_path = path
	_maze_times = {false: {}, true: {}}
	_pachinko_balls = {}
	_paid_back_kept = {}
	_rules_seen = {}
	_handle_power = -1.0
	_cleared = {}
	var loaded := PlayerFileLoad.run(path, VERSION, _read_records, LOAD_WORDS)
	_untouchable = loaded.untouchable
	return loaded.message


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


## Records a finished pachinko game (saved when it won more balls than any before); true
## only when it beat an earlier game's record: a first game sets the record without being
## a "new best", and a game that won nothing never is one.
func record_pachinko_balls(board_id: String, balls: int) -> bool:
	if board_id.is_empty() or balls < 0:
		push_error(
			(
				"record_pachinko_balls: needs a board id and balls >= 0, got '%s', %d"
				% [board_id, balls]
			)
		)
		return false
	var before := best_pachinko_balls(board_id)
	if balls <= before:
		return false
	_pachinko_balls[board_id] = balls
	save()
	return before >= 0


## True once the player has played a pachinko board from its full rules card.
func has_seen_pachinko_rules(board_id: String) -> bool:
	return _rules_seen.has(board_id)


## Remembers (and saves) that the player played `board_id` from its full rules card: later
## games there start with a one-line reminder instead.
func note_pachinko_rules_seen(board_id: String) -> void:
	if board_id.is_empty() or _rules_seen.has(board_id):
		return
	_rules_seen[board_id] = true
	save()


## True once the player has reached `board_id`'s goal (filled its tray).
func has_cleared_pachinko(board_id: String) -> bool:
	return _cleared.has(board_id)


## Remembers (and saves) that the player reached `board_id`'s goal.
func note_pachinko_cleared(board_id: String) -> void:
	if board_id.is_empty() or _cleared.has(board_id):
		return
	_cleared[board_id] = true
	save()


## True once the house's first jackpot (HouseJackpot) has landed on `board_id`.
func has_had_house_jackpot(board_id: String) -> bool:
	return _house_given.has(board_id)


## Remembers (and saves) that the house's first jackpot landed on `board_id`: once a board.
func note_house_jackpot(board_id: String) -> void:
	if board_id.is_empty() or _house_given.has(board_id):
		return
	_house_given[board_id] = true
	save()


## The pachinko handle's strength as the player last left it, or -1 when never kept.
func pachinko_handle_power() -> float:
	return _handle_power


## Keeps (and saves, when it moved) the pachinko handle's strength: the next game and board
## start with it (a play trial turned it on every board, back from 60 each time).
func keep_pachinko_handle_power(power: float) -> void:
	var kept := clampf(roundf(power), 0.0, LaunchHandle.MAX_POWER)
	if is_equal_approx(kept, _handle_power):
		return
	_handle_power = kept
	save()


## Writes the records to the file they were loaded from (nothing when never loaded).
## A file `load_file` must not write over (newer version, or damaged and not movable) is
## left alone: ERR_FILE_NO_PERMISSION, the records stay for this run.
func save() -> Error:
	if _path.is_empty():
		return OK
	if _untouchable:
		return ERR_FILE_NO_PERMISSION
	var sections := [
		["meta", {"version": VERSION}],
		[MAZE_SECTIONS[false], _maze_times[false]],
		[MAZE_SECTIONS[true], _maze_times[true]],
		[MOST_WON_SECTION, _pachinko_balls],
		[PAID_BACK_SECTION, _paid_back_kept],
		["pachinko_rules_seen", _rules_seen],
		["pachinko_player", _player_settings()],
		["pachinko_cleared", _cleared],
		["pachinko_house_jackpot", _house_given],
	]
	var error := IniText.write_file(_path, IniText.format(HEADER % VERSION, sections))
	if error != OK:
		push_error("Could not save best results to %s: %s" % [_path, error_string(error)])
	return error


func _player_settings() -> Dictionary:
	return {"handle_power": _handle_power} if _handle_power >= 0.0 else {}


# Takes every usable record from the sections of a file of `version`; returns the records
# it could not use (a few named, then a count).
func _read_records(sections: Dictionary, version: int) -> PackedStringArray:
	var refused := PackedStringArray()
	if version == 1:
		var legacy: Dictionary = sections.get(LEGACY_MAZE_SECTION, {})
		_read_maze_times(legacy, false, refused)
	else:
		for hard: bool in MAZE_SECTIONS:
			var section: Dictionary = sections.get(MAZE_SECTIONS[hard], {})
			_read_maze_times(section, hard, refused)
	var most_won: Dictionary = sections.get(MOST_WON_SECTION, {})
	var paid_back: Dictionary = sections.get(PAID_BACK_SECTION, {})
	_read_ball_counts(most_won, _pachinko_balls, refused)
	_read_ball_counts(paid_back, _paid_back_kept, refused)
	for flags: Array in [
		["pachinko_rules_seen", _rules_seen],
		["pachinko_cleared", _cleared],
		["pachinko_house_jackpot", _house_given],
	]:
		var section: Dictionary = sections.get(flags[0], {})
		var kept: Dictionary = flags[1]
		_read_flags(section, kept)
	var player: Dictionary = sections.get("pachinko_player", {})
	var handle: Variant = player.get("handle_power", -1.0)
	var strength: float = handle if handle is float or handle is int else NAN
	if is_finite(strength) and strength >= 0.0:
		_handle_power = clampf(strength, 0.0, LaunchHandle.MAX_POWER)
	elif player.has("handle_power"):
		refused.append("the handle's strength")
	if refused.size() > MAX_LISTED:
		var more := refused.size() - MAX_LISTED
		refused.resize(MAX_LISTED)
		refused.append("%d more" % more)
	return refused


# Takes the boards marked true in `section` into `flags`.
static func _read_flags(section: Dictionary, flags: Dictionary) -> void:
	for board_id: String in section:
		if not board_id.is_empty() and section[board_id] is bool and section[board_id]:
			flags[board_id] = true


# Takes every usable count of balls per board from `section` into `counts`.
func _read_ball_counts(section: Dictionary, counts: Dictionary, refused: PackedStringArray) -> void:
	for board_id: String in section:
		var balls: Variant = section[board_id]
		var number: float = balls if balls is float or balls is int else NAN
		if board_id.is_empty() or not is_finite(number) or number < 0 or number > MAX_BALLS:
			refused.append(_shown(board_id))
		else:
			counts[board_id] = int(number)


func _read_maze_times(section: Dictionary, hard: bool, refused: PackedStringArray) -> void:
	var times: Dictionary = _maze_times[hard]
	for board_id: String in section:
		var seconds: Variant = section[board_id]
		var time: float = seconds if seconds is float or seconds is int else NAN
		if board_id.is_empty() or not is_finite(time) or time <= 0.0:
			refused.append(_shown(board_id))
		else:
			times[board_id] = time


# A board id as a message shows it: short, with control characters visible.
static func _shown(board_id: String) -> String:
	return "'%s'" % board_id.left(40).c_escape()
