extends GutTest
## The play analysis samples the powers a player fires. In a contact-free run (nothing
## moving on a plain board) every shot of one power follows one path, so shots that share a
## power are one sample counted many times. On a coarse power grid 10000 shots were
## some 400 paths: the return was a 400-path estimate whose error (about 0.1) the reported
## interval (about 0.025, as if every shot were new) did not show, and the autoplay, whose
## powers are in hundredths, paid 0.07 to 0.1 more than the analysis said on Tulip Garden.


func _classic() -> BoardLevel:
	return BoardLoader.load_board("res://levels/pachinko/classic.board").level


func test_the_analysis_fires_powers_on_the_rules_own_grid() -> void:
	assert_eq(AnalysisPlan.POWER_STEP, PachinkoRules.POWER_STEP, "a shot's power in hundredths")
	for power: float in [0.0, 0.01, 12.34, 50.5, 99.99, 100.0]:
		var level := AnalysisPlan.level_of(power)
		assert_almost_eq(AnalysisPlan.power_of(level), power, 1e-9, "power %s" % power)


func test_every_shot_gets_a_power_of_its_own() -> void:
	var plan := AnalysisPlan.create(_classic(), 2000, 7)
	var seen := {}
	for c in plan.chunk_count():
		for q in plan.chunk_levels(c):
			seen[q] = true
	# Drawn without putting back: no repeat. (2000 independent draws from 10001 powers
	# repeat about 10% of them; from 401 they could not give more than 401.)
	assert_eq(seen.size(), 2000, "distinct powers in 2000 shots")


func test_a_run_as_long_as_the_grid_fires_every_power_once() -> void:
	# With independent draws 10001 shots miss about a third of the powers and fire others
	# two or three times: the return then depended on which, by about ±0.02 on Classic.
	var plan := AnalysisPlan.create(_classic(), AnalysisPlan.level_count(), 4)
	var count := PackedInt32Array()
	count.resize(AnalysisPlan.level_count())
	for c in plan.chunk_count():
		for q in plan.chunk_levels(c):
			count[q] += 1
	assert_eq(count.count(1), AnalysisPlan.level_count(), "each power exactly once")


func test_the_powers_still_come_in_random_order_and_stay_in_range() -> void:
	var plan := AnalysisPlan.create(_classic(), 500, 9)
	plan.power_from = 20.0
	plan.power_to = 40.0
	var levels := plan.chunk_levels(0)
	var rising := 0
	for k in levels.size():
		assert_between(AnalysisPlan.power_of(levels[k]), 20.0, 40.0)
		if k > 0 and levels[k] > levels[k - 1]:
			rising += 1
	# Shuffled, a shot's power is above the one before about half the time, 125 ± 8 of
	# 249 (sorted: always; a played run needs random order, as the balls in play depend on
	# the shots before).
	assert_between(rising, 95, 155, "shots in shuffled order")
	var again := AnalysisPlan.create(_classic(), 500, 9)
	again.power_from = 20.0
	again.power_to = 40.0
	assert_eq(again.chunk_levels(0), levels, "the same plan draws the same powers")


func test_shots_of_one_power_follow_one_path() -> void:
	var plan := AnalysisPlan.create(_classic(), 40, 3)
	plan.played = false
	plan.power_from = 63.0
	plan.power_to = 63.0
	var tally := PachinkoAnalysis.new(plan).run()
	var ends := 0
	for p in tally.pocket_count:
		ends += 1 if tally.pocket_hits(p) > 0 else 0
	var drained := AnalysisTally.total(tally.band_drained)
	ends += 1 if drained > 0 else 0
	assert_eq(ends, 1, "40 shots of power 63 all end in one place")
	assert_eq(tally.total_shots(), 40)
