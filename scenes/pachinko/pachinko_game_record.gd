class_name PachinkoGameRecord
extends RefCounted
## What one pachinko game leaves in the player's save file: the most balls it won (its
## CupPeak) toward the board's best, and the handle's power for the next game. A game
## left before its tray ran dry (Other boards, Restart, Quit) counts too: a play trial left
## Hanami at 277 balls and its card said "Not played yet".

## The game's most balls won above the tray's start.
var cup_peak: CupPeak

var _level: BoardLevel
var _rules: PachinkoRules


func _init(level: BoardLevel, rules: PachinkoRules) -> void:
	_level = level
	_rules = rules
	cup_peak = CupPeak.new(rules)


## The balls this game has won so far.
func won() -> int:
	return cup_peak.won()


## Keeps a game being left: the handle's power always; its balls won only while it is
## still played and won something (a game that ended was kept by `finish`).
func keep_left_game() -> void:
	App.keep_pachinko_handle_power(_rules.handle.power)
	if _rules.state == PachinkoRules.State.PLAYING and won() > 0:
		App.record_pachinko_balls(_level.board_id, won())


## Keeps a game that ended; true when its balls won beat the board's best.
func finish() -> bool:
	var new_best := App.record_pachinko_balls(_level.board_id, won())
	App.keep_pachinko_handle_power(_rules.handle.power)
	return new_best
