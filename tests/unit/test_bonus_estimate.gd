extends GutTest
## BonusEstimate: what tulips and jackpots add to the return, from hand-made tallies whose
## rates give figures worked out on paper.

const ROLE := BonusPocketSpec.Role
## A player holding the handle: the pace the figures below were worked out for.
const HANDLE := LaunchHandle.INTERVAL


# A start pocket (2 symbols), an attacker (pays 10, 6 s or 10 catches) and a tulip (pays 4).
func _level() -> BoardLevel:
	var level := BoardLevel.new()
	var start := BonusPocketSpec.of_role(ROLE.START, Vector2(300, 300), 26.0, 26.0, 2)
	start.symbols = 2
	var attacker := BonusPocketSpec.of_role(ROLE.ATTACKER, Vector2(350, 500), 60.0, 36.0, 10)
	attacker.open_seconds = 6.0
	attacker.open_catches = 10
	var tulip := BonusPocketSpec.of_role(ROLE.TULIP, Vector2(200, 300), 26.0, 26.0, 4)
	var specs: Array[BonusPocketSpec] = [start, attacker, tulip]
	level.bonus_pockets = specs
	return level


# 1000 shots in band 2: `hits` catches per pocket id, the rest drained.
func _tally(hits: Array[int]) -> AnalysisTally:
	var tally := AnalysisTally.new(3, Vector2(700, 700))
	var caught := 0
	for pocket in hits.size():
		for k in hits[pocket]:
			tally.record(2, AnalysisTally.Outcome.POCKETED, pocket, 1)
		caught += hits[pocket]
	for k in 1000 - caught:
		tally.record(2, AnalysisTally.Outcome.DRAINED)
	return tally


func test_tulips_and_jackpots_add_what_the_model_says() -> void:
	var shut := _tally([100, 0, 100])
	var open := _tally([100, 500, 300])
	var figures := BonusEstimate.estimate(_level(), shut, open, -1, HANDLE)
	# Tulip: alternating 2 * 0.1 * 0.3 / 0.4 = 0.15 a shot, 0.05 more than shut, 4 balls each.
	assert_almost_eq(figures["tulip_return"], 0.2, 1e-6)
	# A ball every 0.6 s; spins at 0.1 a shot (0.167 a second) are more than the reels can
	# turn: one per 1.9 + 0.5 * 2.0 + 0.5 s (half are reaches) plus a quarter of a jackpot's
	# 10 rounds of 6 s and 9 breaks of 1.5 s: 1 / 21.775 a second; a quarter are jackpots.
	var per_shot := 0.6 / 21.775 / 4.0
	assert_almost_eq(figures["jackpots_per_1000"], per_shot * 1000.0, 1e-6)
	assert_almost_eq(figures["jackpots_per_hour"], per_shot * 3600.0 / 0.6, 1e-6)
	# A round: 10 balls in 6 s, half caught: 5 catches of 10 balls; a jackpot: 10 rounds.
	assert_almost_eq(figures["round_value"], 50.0, 1e-6)
	assert_almost_eq(figures["jackpot_payout"], 500.0, 1e-6)
	assert_almost_eq(BonusEstimate.added_return(figures), 0.2 + per_shot * 500.0, 1e-6)
	var band := BonusEstimate.estimate(_level(), shut, open, 2, HANDLE)
	assert_almost_eq(band["jackpot_return"], per_shot * 500.0, 1e-6, "band 2 holds every shot")
	var empty := BonusEstimate.estimate(_level(), shut, open, 0)
	assert_eq(BonusEstimate.added_return(empty), 0.0, "a band without shots adds nothing")


func test_the_reels_cap_the_spins() -> void:
	# Every other shot reaches a start pocket: far more than the reels can turn.
	var shut := _tally([500, 0, 0])
	var open := _tally([500, 500, 0])
	var figures := BonusEstimate.estimate(_level(), shut, open, -1, HANDLE)
	# One spin per 3.4 s + 0.25 * (10 * 6 s + 9 * 1.5 s) = 21.775 s; 0.6 s a shot.
	assert_almost_eq(figures["jackpots_per_1000"], 1000.0 * 0.6 / 21.775 / 4.0, 1e-6)


func test_by_default_the_pace_is_the_autoplays_single_shots() -> void:
	assert_almost_eq(BonusEstimate.SHOT_INTERVAL, 0.9, 1e-9, "a pause of 0.6 to 1.2 s")
	var shut := _tally([100, 0, 100])
	var open := _tally([100, 500, 300])
	var figures := BonusEstimate.estimate(_level(), shut, open)
	# A round: 6 s / 0.9 s = 6.67 balls, half caught: 3.33 catches of 10 balls.
	assert_almost_eq(figures["round_value"], 100.0 / 3.0, 1e-6)
	# Spins at 0.1 a shot, 0.111 a second, a quarter jackpots: the reels keep up with them
	# until the jackpots' rounds take their time: at most one spin per 3.4 s + 0.25 * (10
	# * 6 s + 9 * 1.5 s) = 21.775 s.
	assert_almost_eq(figures["jackpots_per_1000"], 1000.0 * 0.9 / 21.775 / 4.0, 1e-6)
	assert_almost_eq(figures["tulip_return"], 0.2, 1e-6, "tulips count per shot, not per second")


func test_a_bonus_board_report_has_an_expected_return_only_with_the_open_run() -> void:
	var loaded := BoardLoader.load_board("res://levels/pachinko/fever.board")
	var plan := AnalysisPlan.create(loaded.level, 250, 3)
	var shut := PachinkoAnalysis.new(plan).run()
	assert_false(AnalysisReport.build(plan, shut, 1.0).has("expected_return"))
	var open := PachinkoAnalysis.new(plan.with_bonus_open()).run()
	var report := AnalysisReport.build(plan, shut, 1.0, open)
	var bonus: Dictionary = report["bonus"]
	assert_almost_eq(
		report["expected_return"],
		report["return"] + bonus["tulip_return"] + bonus["jackpot_return"],
		1e-4
	)
	assert_gt(open.pocket_hits(BonusGeometry.pocket_id(loaded.level, 1)), 0, "open lid catches")
