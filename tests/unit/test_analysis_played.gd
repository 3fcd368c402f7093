extends GutTest
## A played analysis (`--played`) fires its shots as the autoplay does: one at a time, at
## its pace, among the balls still in play, with ball contacts on. Measured shot by shot on
## Classic against the same powers fired alone: about one shot in thirty ends elsewhere,
## more often out of a pocket than into one. A run whose balls flew through each other
## (the analysis before) missed that, and the autoplay paid less than it said.

const SHOTS := 250
const SEED := 2


func _classic() -> BoardLevel:
	return BoardLoader.load_board("res://levels/pachinko/classic.board").level


func _plan() -> AnalysisPlan:
	var plan := AnalysisPlan.create(_classic(), SHOTS, SEED)
	plan.played = true
	return plan


func _launch(plan: AnalysisPlan) -> LaunchTable:
	return LaunchCalibration.table(plan.level)


func test_a_played_chunk_fires_at_the_autoplays_pace_among_the_balls_in_play() -> void:
	var plan := _plan()
	var chunk := PlayedShotChunk.new(plan, _launch(plan))
	assert_true(chunk.run(0))
	var tally := chunk.tally
	assert_eq(tally.total_shots(), SHOTS, "every shot ends in a count")
	assert_eq(AnalysisTally.total(tally.band_stuck), 0, "no ball left stuck")
	var step_seconds := 1.0 / BoardWorldFactory.tuning_for(plan.level).fixed_hz
	var seconds_per_shot := tally.steps * step_seconds / SHOTS
	# A pause of 0.6 to 1.2 s (0.9 s on average, on the display's frames), and at the end
	# the last balls' few seconds of flight spread over the chunk's shots.
	assert_between(seconds_per_shot, 0.9, 1.0, "seconds of play per shot")
	# The autoplay on Classic keeps about seven balls in play (13 at most in 900 s).
	var in_flight := float(tally.ball_steps) / tally.steps
	assert_between(in_flight, 4.0, 10.0, "balls in play at once, on average")


func test_balls_in_play_knock_some_shots_elsewhere() -> void:
	var plan := _plan()
	var played := PlayedShotChunk.new(plan, _launch(plan))
	assert_true(played.run(0))
	plan.played = false
	var alone := PachinkoShotChunk.new(plan, _launch(plan))
	assert_true(alone.run(0))
	# The same powers in the same order: only the other balls make a difference.
	assert_eq(played.tally.band_shots, alone.tally.band_shots)
	var moved := 0
	for i in played.tally.band_pocket_hits.size():
		moved += absi(played.tally.band_pocket_hits[i] - alone.tally.band_pocket_hits[i])
	assert_gt(moved, 0, "some catches differ when balls meet")
	assert_lt(moved, SHOTS / 5, "but most shots end as they would alone")


func test_a_played_report_says_so_and_is_cached_apart() -> void:
	var plan := AnalysisPlan.create(_classic(), 10, 1)
	plan.played = true
	var report := AnalysisReport.build(plan, AnalysisTally.new(5, plan.level.size), 1.0)
	assert_true(report["played"], "the report says how its shots were fired")
	var lone := AnalysisPlan.create(_classic(), 10, 1)
	assert_false(lone.played, "a plan fires its balls alone unless asked to play them")
	assert_ne(AnalysisCache.key_for(plan), AnalysisCache.key_for(lone))
