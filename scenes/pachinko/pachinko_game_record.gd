class_name PachinkoGameRecord
extends RefCounted
## What one pachinko game leaves in the player's save file: its result (the balls it ended
## with less those it started with) toward the board's best, and the handle's power for the
## next game. The balls are those the player holds: the cup's and the launcher's
## (PachinkoRules.balls_to_shoot, the tray's count once it settles); a ball in flight is
## not held. A game left before its tray ran dry (Other boards, Restart, Quit) counts too: a
## play trial left Hanami at 277 balls and its card said "Not played yet". Trial 8: the best
## was the game's highest point (Windmills peaked +16, ended even, and kept 16).

## The balls the game started with.
var start := 0

var _level: BoardLevel
var _rules: PachinkoRules


func _init(level: BoardLevel, rules: PachinkoRules) -> void:
	_level = level
	_rules = rules
	start = level.cup_start_balls


## The balls the player holds now (those in flight are not).
func held() -> int:
	return _rules.balls_to_shoot


## The game's result so far: the balls held less those it started with (below 0: down).
func result() -> int:
	return held() - start


## Keeps a game being left: the handle's power always; its result only while it is still
## played and ahead (a game that ended was kept by `finish`).
func keep_left_game() -> void:
	App.keep_pachinko_handle_power(_rules.handle.power)
	if _rules.state == PachinkoRules.State.PLAYING and result() > 0:
		App.record_pachinko_balls(_level.board_id, result())


## Keeps the result of a game that just cleared its machine toward the board's best, so the
## panel and the board card show it at once (trial 9 read "best none yet" beside "goal 32
## cleared!"); the game goes on and counts again when it is left or ends.
func keep_clear() -> void:
	if result() > 0:
		App.record_pachinko_balls(_level.board_id, result())


## Keeps a game that ended (its tray ran dry: a result of nothing won); true when it beat
## the board's best.
func finish() -> bool:
	var new_best := App.record_pachinko_balls(_level.board_id, maxi(result(), 0))
	App.keep_pachinko_handle_power(_rules.handle.power)
	return new_best
