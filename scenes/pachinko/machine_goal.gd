class_name MachineGoal
extends RefCounted
## A machine's goal in play: watches one game's tray (CupPeak) against the board's target
## (PachinkoGoals), says once when it is reached, and remembers the clear for the board's
## card; `next_board_path` is where Next machine goes. Reached mid-jackpot it waits until
## the jackpot has settled (JackpotSettle): the card must not freeze a jackpot (trial 6).

## The tray reached the goal this game, `won` balls above the start.
signal reached(won: int)

var _level: BoardLevel
var _peak: CupPeak
var _done := false
# Reached while a jackpot was on: said once it settles.
var _waiting := false
var _settle: JackpotSettle


## Watches the game `rules` on `level`, its tray followed by `peak`.
func _init(level: BoardLevel, rules: PachinkoRules, peak: CupPeak) -> void:
	_level = level
	_peak = peak
	# connected after the peak's own: it has seen this change first
	rules.cup_changed.connect(_on_cup_changed)
	_settle = JackpotSettle.new(rules)
	_settle.settled.connect(_on_settled)


## True once this game reached the goal.
func is_reached() -> bool:
	return _done


## The board after `level` in the pachinko list (the first after the last), "" for none.
static func next_board_path(level: BoardLevel) -> String:
	var boards := BoardLoader.list_boards(BoardLevel.Kind.PACHINKO)
	var paths := PackedStringArray()
	for result in boards:
		if result.ok():
			paths.append(result.path)
	if paths.is_empty():
		return ""
	var here := -1
	for i in boards.size():
		if boards[i].ok() and boards[i].level.board_id == level.board_id:
			here = paths.find(boards[i].path)
	return paths[(here + 1) % paths.size()]


func _on_cup_changed(_count: int) -> void:
	var target := PachinkoGoals.tray_target(_level)
	if _done or target <= 0 or _peak.peak < target:
		return
	_done = true
	App.note_pachinko_cleared(_level.board_id)
	_waiting = true
	_say_when_free()


# Deferred: after the jackpot's own views have had the moment (the card then clears them).
func _on_settled(_paid: int) -> void:
	_say_when_free.call_deferred()


func _say_when_free() -> void:
	if not _waiting or _settle.busy():
		return
	_waiting = false
	reached.emit(_peak.won())
