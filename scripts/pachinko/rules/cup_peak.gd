class_name CupPeak
extends RefCounted
## The most balls a game's cup has held above its start, for the analysis's sessions
## (`peak_won`: how far a game can climb, what a machine's goal is set from). The game's own
## best is its result, not this (PachinkoGameRecord; trial 8). Follows one game's rules.

## The balls the game started with.
var start := 0
## The most balls to shoot (cup and launcher) seen so far.
var peak := 0

var _rules: PachinkoRules


## Follows `rules` from now (a new game starts at its board's start balls).
func _init(rules: PachinkoRules) -> void:
	_rules = rules
	start = rules.level.cup_start_balls
	peak = start
	rules.cup_changed.connect(_on_cup_changed)


## The most balls held above the start so far (0 while the cup never rose past it).
func won() -> int:
	return maxi(peak - start, 0)


func _on_cup_changed(_count: int) -> void:
	peak = maxi(peak, _rules.balls_to_shoot)
