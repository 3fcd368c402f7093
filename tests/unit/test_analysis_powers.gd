extends GutTest
## The play analysis samples the powers a player fires. In its world (no ball contacts,
## nothing moving on a plain board) every shot of one power follows one path, so shots that
## share a power are one sample counted many times. On a coarse power grid 10000 shots were
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


func test_almost_every_shot_gets_a_power_of_its_own() -> void:
	var plan := AnalysisPlan.create(_classic(), 2000, 7)
	var seen := {}
	for c in plan.chunk_count():
		for q in plan.chunk_levels(c):
			seen[q] = true
	# 2000 draws from 10001 powers repeat about 10% of them; from 401 they could not
	# give more than 401.
	assert_gt(seen.size(), 1700, "distinct powers in 2000 shots")


func test_shots_of_one_power_follow_one_path() -> void:
	var plan := AnalysisPlan.create(_classic(), 40, 3)
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
