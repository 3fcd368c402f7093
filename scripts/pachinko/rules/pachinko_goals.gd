class_name PachinkoGoals
extends RefCounted
## Each machine's goal: fill the tray to a number of balls. Reaching it clears the machine.
## The numbers come from `--sessions=20 --seed=1` (scripts/analysis/pachinko_sessions.gd,
## its peak_won spread; rules 5, Fever and Hanami rules 6): each is the most balls held
## above the start that the autoplay's random shots reached in 6 of 20 sessions (30 %), so
## a player who aims at the paying strengths clears it more often than not-quite-a-third.

## Board id -> the tray's target (balls to shoot, start included).
const TRAY_TARGETS := {
	"pachinko_classic": 32,  # start 25; won >= 7 in 6 of 20
	"pachinko_tulips": 60,  # start 50; won >= 10 in 6 of 20
	"pachinko_windmills": 85,  # start 60; won >= 25 in 6 of 20
	"pachinko_fever": 127,  # start 100; won >= 27 in 6 of 20 (rules 6; 135 under rules 5)
	"pachinko_hanami": 114,  # start 100; won >= 14 in 6 of 20 (rules 6; 120 under rules 5)
}


## The tray's target on `level` (0: the machine has no goal, as a player's own board).
static func tray_target(level: BoardLevel) -> int:
	return TRAY_TARGETS.get(level.board_id, 0)


## The goal in a player's words ("Fill the tray: 135 balls"), "" for none.
static func words(level: BoardLevel) -> String:
	var target := tray_target(level)
	return "Fill the tray: %d balls" % target if target > 0 else ""
