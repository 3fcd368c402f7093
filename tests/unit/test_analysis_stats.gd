extends GutTest
## The analysis statistics on counts whose answers are known by hand.


func test_wilson_interval_matches_known_values() -> void:
	# 50 of 100: the Wilson 95% interval is about [0.4038, 0.5962].
	var half := AnalysisStats.wilson(50, 100)
	assert_almost_eq(half.x, 0.4038, 0.0005)
	assert_almost_eq(half.y, 0.5962, 0.0005)
	# 0 of 100: the lower bound is 0 and the upper z²/(n+z²) ≈ 0.0370.
	var none := AnalysisStats.wilson(0, 100)
	assert_almost_eq(none.x, 0.0, 1e-12)
	assert_almost_eq(none.y, 0.0370, 0.0005)
	assert_eq(AnalysisStats.wilson(0, 0), Vector2(0.0, 1.0), "no trials: nothing known")


func test_mean_half_width_uses_the_sample_variance() -> void:
	# Values 0, 4, 0, 4: mean 2, sample variance 16/3, half-width 1.96·sqrt(16/3/4).
	var expected := AnalysisStats.Z95 * sqrt(16.0 / 3.0 / 4.0)
	assert_almost_eq(AnalysisStats.mean_half_width(8, 32, 4), expected, 1e-9)
	assert_eq(AnalysisStats.mean_half_width(8, 16, 4), 0.0, "2, 2, 2, 2: no spread")
	assert_eq(AnalysisStats.mean_half_width(1, 1, 1), INF, "one value has no variance")


func test_a_pocket_is_dead_only_when_dead_in_every_band() -> void:
	var tally := AnalysisTally.new(2, Vector2(10, 10))
	for band in tally.band_count:
		for i in 2000:
			tally.record(band, AnalysisTally.Outcome.DRAINED)
	# Pocket 0 never caught: upper bound 0.19% < 0.5% in every band. Pocket 1 caught 20
	# times in the strongest band only: alive.
	for i in 20:
		tally.record(4, AnalysisTally.Outcome.POCKETED, 1, 3)
	assert_eq(AnalysisStats.dead_pockets(tally), PackedInt32Array([0]))


func test_too_few_shots_never_call_a_pocket_dead() -> void:
	var tally := AnalysisTally.new(1, Vector2(10, 10))
	for band in tally.band_count:
		for i in 100:
			tally.record(band, AnalysisTally.Outcome.DRAINED)
	assert_true(AnalysisStats.dead_pockets(tally).is_empty(), "100 shots a band cannot tell")
	assert_true(AnalysisStats.dead_pockets(AnalysisTally.new(1)).is_empty(), "no shots at all")


func test_total_variation_distance() -> void:
	var p := PackedFloat64Array([0.5, 0.5, 0.0])
	var q := PackedFloat64Array([0.0, 0.5, 0.5])
	assert_almost_eq(AnalysisStats.total_variation(p, q), 0.5, 1e-12)
	assert_eq(AnalysisStats.total_variation(p, p), 0.0)
	assert_eq(AnalysisStats.total_variation(p, PackedFloat64Array()), -1.0)


func test_aim_distance_compares_weakest_and_strongest_band_catches() -> void:
	var tally := AnalysisTally.new(2, Vector2(10, 10))
	tally.record(0, AnalysisTally.Outcome.POCKETED, 0, 4)
	tally.record(4, AnalysisTally.Outcome.POCKETED, 1, 4)
	assert_almost_eq(AnalysisStats.aim_distance(tally), 1.0, 1e-12, "different pockets")
	tally.record(4, AnalysisTally.Outcome.POCKETED, 0, 4)
	assert_almost_eq(AnalysisStats.aim_distance(tally), 0.5, 1e-12)
	assert_eq(AnalysisStats.aim_distance(AnalysisTally.new(2)), -1.0, "no catches: unknown")


func test_tally_records_values_and_merges() -> void:
	var a := AnalysisTally.new(2, Vector2(10, 10))
	a.record(1, AnalysisTally.Outcome.POCKETED, 1, 5)
	a.record(1, AnalysisTally.Outcome.RETURNED)
	var b := AnalysisTally.new(2, Vector2(10, 10))
	b.record(1, AnalysisTally.Outcome.DRAINED)
	b.density[3] = 7
	a.merge(b)
	assert_eq(a.total_shots(), 3)
	assert_eq(a.band_value[1], 6, "payout 5 plus 1 for the ball that rolled back")
	assert_eq(a.band_value_sq[1], 26)
	assert_eq(a.pocket_hits(1), 1)
	assert_eq(a.density[3], 7)
