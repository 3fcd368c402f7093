extends GutTest
## The pachinko play analysis against the real physics: a board with a known answer, the
## same figures on any thread count, the rail hand-over changing nothing, cancel.

const TIMING_KEYS := ["wall_s", "shots_per_s", "threads"]


func _classic() -> BoardLevel:
	return BoardLoader.load_board("res://levels/pachinko/classic.board").level


func test_a_board_without_pins_returns_nothing_every_power_clears_the_rail() -> void:
	# No pins, no pockets: every power clears the rail (none rolls back) and every ball
	# drains, so the return is 0.
	var bare := _classic().duplicate_level()
	bare.pockets = []
	bare.pins = PackedVector2Array()
	bare.pin_pocket = PackedInt32Array()
	bare.pin_special = PackedByteArray()
	var plan := AnalysisPlan.create(bare, 400, 3)
	var tally := PachinkoAnalysis.new(plan).run()
	var report := AnalysisReport.build(plan, tally, 1.0)
	assert_eq(report["shots"], 400)
	assert_eq(report["returned"], 0, "no power rolls back")
	assert_eq(report["drained"], 400)
	assert_eq(report["return"], 0.0)
	assert_eq(report["bands"][0]["entry_x"]["median"], -1, "no pin to meet")


func test_a_fixed_power_gives_one_outcome_with_no_spread() -> void:
	var plan := AnalysisPlan.create(_classic(), 60, 1)
	plan.played = false  # balls alone: no other ball to knock one off its path
	plan.power_from = 70.0
	plan.power_to = 70.0
	var report := AnalysisReport.build(plan, PachinkoAnalysis.new(plan).run(), 1.0)
	# every shot lands in the same place: the return is nothing or one pocket's payout
	var outcomes: Array[float] = [0.0]
	for pocket in plan.level.pockets:
		outcomes.append(float(pocket.payout))
	var got: float = report["return"]
	assert_has(outcomes, got, "every shot the same (%s)" % got)
	assert_eq(report["return_ci95"], 0.0)
	var band: Dictionary = report["bands"][3]
	assert_eq(band["shots"], 60, "power 70 lies in the fourth band")


func test_figures_are_the_same_on_one_and_two_threads() -> void:
	var reports: Array[Dictionary] = []
	for threads in [1, 2]:
		var plan := AnalysisPlan.create(_classic(), 520, 11)
		plan.threads = threads
		var analysis := PachinkoAnalysis.new(plan)
		var report := AnalysisReport.build(plan, analysis.run(), analysis.wall_seconds)
		for key: String in TIMING_KEYS:
			report.erase(key)
		reports.append(report)
	assert_eq(JSON.stringify(reports[0]), JSON.stringify(reports[1]))
	assert_gt(reports[0]["pockets"][1]["hits"], 0, "a real run catches balls")


func test_the_rail_hand_over_changes_no_outcome() -> void:
	# The same chunk fired from the launcher (no table) and from the rail exits.
	var plan := AnalysisPlan.create(_classic(), 120, 5)
	plan.played = false  # the hand-over is the contact-free run's shortcut
	var analysis := PachinkoAnalysis.new(plan)
	var with_table := analysis.run()
	var launch: LaunchTable = LaunchCalibration.table(plan.level)
	var full := PachinkoShotChunk.new(plan, launch, null)
	assert_true(full.run(0))
	assert_eq(with_table.band_pocket_hits, full.tally.band_pocket_hits)
	assert_eq(with_table.band_value, full.tally.band_value)
	assert_eq(with_table.band_returned, full.tally.band_returned)
	assert_lt(with_table.ball_steps, full.tally.ball_steps, "the climbs were not simulated")


func test_climbs_handed_on_to_the_bonus_open_run_give_its_own_figures() -> void:
	# The CLI's second run (bonus pockets held open) takes the first run's rail climbs.
	var level := BoardLoader.load_board("res://levels/pachinko/fever.board").level
	var plan := AnalysisPlan.create(level, 250, 2)
	var first := PachinkoAnalysis.new(plan)
	first.run()
	var fresh := PachinkoAnalysis.new(plan.with_bonus_open()).run()
	var reused := PachinkoAnalysis.new(plan.with_bonus_open())
	reused.reuse_climbs(first.climb_table())
	reused.profile = AnalysisProfile.new()
	var tally := reused.run()
	assert_eq(reused.profile.climb_groups, 0, "no climb run again")
	var a := AnalysisReport.build(plan, fresh, 1.0)
	var b := AnalysisReport.build(plan, tally, 1.0)
	assert_eq(JSON.stringify(b), JSON.stringify(a), "the same figures as its own climbs")
	assert_eq(tally.ball_steps, fresh.ball_steps)
	assert_eq(tally.density, fresh.density)
	# Climbs that miss a level the plan fires are not used: every climb runs again.
	var other := PachinkoAnalysis.new(AnalysisPlan.create(level, 250, 3))
	other.reuse_climbs(first.climb_table())
	other.profile = AnalysisProfile.new()
	other.run()
	assert_gt(other.profile.climb_groups, 0, "a table that misses levels is not used")


func test_climbs_stopped_at_the_hand_over_leave_the_same_first_pins() -> void:
	# A contact-free run stops each climb at its hand-over; the chunks record the first pins
	# met past it, which must be the ones a climb followed on to the first pin finds.
	var plan := AnalysisPlan.create(_classic(), 250, 4)
	var stopped := PachinkoAnalysis.new(plan)
	stopped.profile = AnalysisProfile.new()
	var tally := stopped.run()
	var table := stopped.climb_table()
	assert_false(table.to_first_pin, "a contact-free run stops at the hand-over")
	var later := 0
	for q in plan.chunk_levels(0):
		later += 1 if table.entry_after_exit(q) else 0
	assert_gt(later, 100, "most first pins come after the hand-over")
	var followed := RailExitTable.new()
	var needed := PackedByteArray()
	needed.resize(AnalysisPlan.level_count())
	for q in plan.chunk_levels(0):
		needed[q] = 1
	var launch: LaunchTable = LaunchCalibration.table(plan.level)
	var climbs := AnalysisProfile.new()
	for group in RailExitTable.groups_for(needed):
		followed.store(RailClimber.climb_group(plan.level, launch, group, climbs), group)
	var again := PachinkoAnalysis.new(plan)
	again.reuse_climbs(followed)
	var tally_followed := again.run()
	assert_eq(tally.band_entry, tally_followed.band_entry, "the same first pins")
	var a := AnalysisReport.build(plan, tally, 1.0)
	var b := AnalysisReport.build(plan, tally_followed, 1.0)
	assert_eq(JSON.stringify(a), JSON.stringify(b), "the same figures")
	assert_eq(tally.density, tally_followed.density, "the same heat map")
	assert_lt(stopped.profile.climb_ball_steps, climbs.climb_ball_steps * 0.7, "shorter climbs")


func test_a_played_run_climbs_on_to_the_first_pin() -> void:
	# Its shots meet other balls, so their first pins come from the climbs: a table that
	# stopped at the hand-over is not taken.
	var plan := AnalysisPlan.create(_classic(), 250, 4)
	var contact_free := PachinkoAnalysis.new(plan)
	contact_free.run()
	var played_plan := AnalysisPlan.create(_classic(), 250, 4)
	played_plan.played = true
	var played := PachinkoAnalysis.new(played_plan)
	played.reuse_climbs(contact_free.climb_table())
	assert_true(played.start())
	assert_true(played.climb_table().to_first_pin, "its own climbs, to the first pin")
	played.cancel()
	while not played.poll():
		OS.delay_msec(5)


func test_each_band_reports_where_its_shots_first_met_a_pin() -> void:
	# 400 shots a band: the weak fifth's entries cluster at x 541 and 554..567 (median 554
	# over 10000 shots), so 100 shots a band could put the median on either side of 548.
	var plan := AnalysisPlan.create(_classic(), 2000, 3)
	plan.played = false  # the entries come from the rail climbs either way; this is faster
	var report := AnalysisReport.build(plan, PachinkoAnalysis.new(plan).run(), 1.0)
	var bands: Array = report["bands"]
	var weak: Dictionary = bands[0]["entry_x"]
	var strong: Dictionary = bands[4]["entry_x"]
	for entry: Dictionary in [weak, strong]:
		assert_true(entry["p10"] <= entry["median"] and entry["median"] <= entry["p90"], str(entry))
	# Classic's ring spans x 20..680: weak shots drop in beside the rail on the right, strong
	# ones reach the left third.
	assert_gte(int(weak["median"]), 548, "weak fifth: %s" % weak)
	assert_lte(int(strong["median"]), 240, "strong fifth: %s" % strong)


func test_entry_percentiles_come_from_the_counts() -> void:
	var tally := AnalysisTally.new(1, Vector2(700, 700))
	for x: float in [100.0, 200.0, 300.0, 400.0, 500.0, NAN]:
		tally.record_entry(1, x)
	assert_eq(tally.entry_percentile(1, 0.5), 300, "the middle of five")
	assert_eq(tally.entry_percentile(1, 0.1), 100)
	assert_eq(tally.entry_percentile(1, 0.9), 500)
	assert_eq(tally.entry_percentile(0, 0.5), -1, "a band with no entries says so")


func test_cancel_stops_a_background_run() -> void:
	var plan := AnalysisPlan.create(_classic(), 5000, 2)
	plan.threads = 2
	var analysis := PachinkoAnalysis.new(plan)
	assert_true(analysis.start())
	analysis.cancel()
	var started := Time.get_ticks_msec()
	while not analysis.poll():
		OS.delay_msec(5)
	assert_eq(analysis.phase, PachinkoAnalysis.Phase.CANCELLED)
	assert_lt(Time.get_ticks_msec() - started, 5000, "stopped long before 5000 shots")
	var partial := analysis.tally()
	assert_true(partial == null or partial.total_shots() < 5000)


func test_a_plan_that_cannot_run_is_refused_with_a_reason() -> void:
	var maze := BoardLoader.load_board("res://levels/maze/classic.board").level
	var plan := AnalysisPlan.create(maze, 10, 1)
	assert_string_contains(plan.problem(), "pachinko board")
	assert_null(PachinkoAnalysis.new(plan).run())
	assert_push_error("pachinko board")
	var bad := AnalysisPlan.create(_classic(), 0, 1)
	assert_string_contains(bad.problem(), "at least one shot")
	bad.shots = 10
	bad.power_to = 150.0
	assert_string_contains(bad.problem(), "0..100")
