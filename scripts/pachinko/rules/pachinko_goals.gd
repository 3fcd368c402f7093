class_name PachinkoGoals
extends RefCounted
## Each machine's goal: fill the tray to a number of balls. Reaching it clears the machine.
## The plain machines' numbers come from `--sessions=20 --seed=1`
## (scripts/analysis/pachinko_sessions.gd, its peak_won spread; rules 5): each is the most
## balls held above the start that the autoplay's random shots reached in 6 of 20 sessions
## (30 %). The reel machines' (rules 8, trial 8: Fever's 127 meant nothing once a jackpot
## paid 714) ask for a little less than one jackpot played at the attacker brings
## (`tools/jackpot_sample.gd --aim`: Fever +81, Hanami +117 held from its start to its
## end) and far more than streaming alone brings in the first minutes.

## Board id -> the tray's target (balls to shoot, start included).
const TRAY_TARGETS := {
	"pachinko_classic": 32,  # start 25; won >= 7 in 6 of 20
	"pachinko_tulips": 60,  # start 50; won >= 10 in 6 of 20
	"pachinko_windmills": 85,  # start 60; won >= 25 in 6 of 20
	"pachinko_fever": 170,  # start 100; an aimed jackpot nets +81 (127 under rules 7)
	"pachinko_hanami": 180,  # start 100; an aimed jackpot nets +117 (114 under rules 7)
}


## The tray's target on `level` (0: the machine has no goal, as a player's own board).
static func tray_target(level: BoardLevel) -> int:
	return TRAY_TARGETS.get(level.board_id, 0)


## The goal in a player's words ("Fill the tray: 135 balls"), "" for none.
static func words(level: BoardLevel) -> String:
	var target := tray_target(level)
	return "Fill the tray: %d balls" % target if target > 0 else ""
