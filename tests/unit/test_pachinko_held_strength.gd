extends GutTest
## A play trial held the handle at its best strength and the game never ended: on every
## shipped board one strength paid 1.7 to 2.3 balls a ball (tools/power_returns.gd, the
## handle's spread of 2 points either side). With the spring's spread of LaunchHandle.JITTER
## and the boards' payouts re-tuned (rules 5), the strength that paid most before pays far
## a fifth less or more: measured here as the handle fires, every power within JITTER of it,
## the bonus layer's estimate included. (No board holds every strength under 0.97 yet: its
## best strength still pays 1.1 to 1.5, see README "Held strength".)

## The strength each board paid most at before (rules 4) and what it paid then.
const WORST_BEFORE := {
	"classic": [74.0, 1.875],
	"tulips": [46.0, 1.866],
	"windmills": [58.0, 1.675],
	"fever": [70.0, 2.191],
	"hanami": [76.0, 2.319],
}
## What such a strength may pay now, as a share of what it paid then at most.
const MOST_SHARE := 0.8
const SHOTS := 600


func _held_return(board: String, strength: float) -> float:
	var level := BoardLoader.load_board("res://levels/pachinko/%s.board" % board).level
	var plan := AnalysisPlan.create(level, SHOTS, 1)
	plan.threads = 2
	plan.power_from = maxf(strength - LaunchHandle.JITTER, 0.0)
	plan.power_to = minf(strength + LaunchHandle.JITTER, 100.0)
	var tally := PachinkoAnalysis.new(plan).run()
	var open: AnalysisTally = null
	if not level.bonus_pockets.is_empty():
		open = PachinkoAnalysis.new(plan.with_bonus_open()).run()
	var report := AnalysisReport.build(plan, tally, 1.0, open)
	return float(report.get("expected_return", report["return"]))


func test_the_handle_spreads_its_balls_over_a_few_pins() -> void:
	assert_gte(LaunchHandle.JITTER, 6.0, "2 points either side let one strength pay forever")


func test_no_board_pays_its_old_best_strength_back_any_more() -> void:
	for board: String in WORST_BEFORE:
		var strength: float = WORST_BEFORE[board][0]
		var ret := _held_return(board, strength)
		gut.p(
			"%s: handle at %d pays %.3f (was %.3f)" % [board, strength, ret, WORST_BEFORE[board][1]]
		)
		var was: float = WORST_BEFORE[board][1]
		assert_lt(ret, was * MOST_SHARE, "%s: the handle held at %d" % [board, strength])
