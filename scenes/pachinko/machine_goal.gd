class_name MachineGoal
extends RefCounted
## A machine's goal in play: watches the balls one game's player holds (the cup's and the
## launcher's) against the board's target (PachinkoGoals), says once when it is reached, and
## remembers the clear for the board's card; `next_board_path` is where Next machine goes.
## Reached mid-jackpot it waits until the jackpot has settled (JackpotSettle), and reached
## in a Gold rush until the rush ends: the card must not freeze either (trials 6 and 9).

## The tray reached the goal this game, `won` balls above the start when it was said.
signal reached(won: int)

var _level: BoardLevel
var _rules: PachinkoRules
var _done := false
# Reached while a jackpot was on: said once it settles.
var _waiting := false
var _settle: JackpotSettle
# What the jackpot the goal waited for paid (-1: it waited for none).
var _jackpot_paid := -1


## Watches the game `rules` on `level`.
func _init(level: BoardLevel, rules: PachinkoRules) -> void:
	_level = level
	_rules = rules
	# the rules tell a payout (ball_won: its pour starts) before the count changes, so the
	# tray has the payout that clears the machine when the card reads it
	rules.cup_changed.connect(_on_cup_changed)
	_settle = JackpotSettle.new(rules)
	_settle.settled.connect(_on_settled)
	rules.gold.rush_changed.connect(_on_rush_changed)


## True once this game reached the goal.
func is_reached() -> bool:
	return _done


## True while the goal is reached but waits for the jackpot or Gold rush under way to end.
func is_waiting() -> bool:
	return _waiting


## What the jackpot the clear waited for paid (its summary card gives way to the clear's
## card, trial 9 never saw one), -1 when the clear waited for no jackpot.
func jackpot_paid() -> int:
	return _jackpot_paid


## Where Next machine goes from `level`: the first board after it in the pachinko list
## (going round from the last to the first) that the player has never played, else the
## first not yet cleared, else simply the next; "" for none. Trial 7 went from Windmills,
## the last, round to Classic, cleared already, and never reached Tulip Garden, unplayed.
static func next_board_path(level: BoardLevel) -> String:
	var paths := PackedStringArray()
	var ids := PackedStringArray()
	for result in BoardLoader.list_boards(BoardLevel.Kind.PACHINKO):
		if result.ok():
			paths.append(result.path)
			ids.append(result.level.board_id)
	var played := PackedByteArray()
	var cleared := PackedByteArray()
	for id in ids:
		played.append(1 if App.best_pachinko_balls(id) >= 0 or App.has_cleared_pachinko(id) else 0)
		cleared.append(1 if App.has_cleared_pachinko(id) else 0)
	var next := next_index(ids.find(level.board_id), played, cleared)
	return paths[next] if next >= 0 else ""


## The index Next machine goes to from board `here` (-1: not in the list) among boards
## whose `played` and `cleared` flags are given in list order: the first after it, going
## round, never played, else not cleared, else the next; -1 when there are none.
static func next_index(here: int, played: PackedByteArray, cleared: PackedByteArray) -> int:
	var count := played.size()
	if count == 0:
		return -1
	for wanted: PackedByteArray in [played, cleared]:
		for step in range(1, count + 1):
			var i := (here + step) % count
			if i != here and wanted[i] == 0:
				return i
	return (here + 1) % count


func _on_cup_changed(_count: int) -> void:
	var target := PachinkoGoals.tray_target(_level)
	if _done or target <= 0 or _rules.balls_to_shoot < target:
		return
	_done = true
	App.note_pachinko_cleared(_level.board_id)
	_waiting = true
	_say_when_free()


# Deferred: after the jackpot's own views have had the moment (the card then clears them).
func _on_settled(paid: int) -> void:
	if _waiting:
		_jackpot_paid = paid
	_say_when_free.call_deferred()


# Trial 9: the card came up as a Gold rush began and froze it at "17 s left".
func _on_rush_changed(active: bool) -> void:
	if not active:
		_say_when_free.call_deferred()


func _say_when_free() -> void:
	if not _waiting or _settle.busy() or _rules.gold.rush_on():
		return
	_waiting = false
	reached.emit(_rules.balls_to_shoot - _level.cup_start_balls)
