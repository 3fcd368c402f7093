extends GutTest
## The session report (`--sessions=N`): a session runs from a full cup to an empty one at
## the autoplay's pace, and the report gives the median and 10th percentile of the sessions'
## lengths, jackpots per hour and what a jackpot paid.

const CLASSIC := "res://levels/pachinko/classic.board"


func _session(seconds: float, jackpot_payouts: Array[int], capped := false) -> Dictionary:
	return {
		"seconds": seconds,
		"shots": int(seconds),
		"balls_won": 10,
		"jackpots": jackpot_payouts.size(),
		"jackpot_payouts": jackpot_payouts,
		"capped": capped,
	}


func test_percentiles_lie_between_the_nearest_ranks() -> void:
	var values := PackedFloat64Array([50.0, 10.0, 40.0, 20.0, 30.0])
	assert_almost_eq(PachinkoSessions.percentile(values, 0.5), 30.0, 1e-9, "the middle one")
	assert_almost_eq(
		PachinkoSessions.percentile(values, 0.1), 14.0, 1e-9, "0.4 of the way from 10 to 20"
	)
	assert_almost_eq(PachinkoSessions.percentile(values, 1.0), 50.0, 1e-9)
	assert_eq(PachinkoSessions.percentile(PackedFloat64Array(), 0.5), 0.0, "no sessions, no length")


func test_the_report_gives_median_p10_jackpots_per_hour_and_mean_payout() -> void:
	var sessions: Array[Dictionary] = [
		_session(600.0, [120, 80]),
		_session(100.0, []),
		_session(300.0, []),
		_session(1800.0, [150], true),
		_session(200.0, []),
	]
	var report := PachinkoSessions.summarize(sessions)
	assert_eq(report["sessions"], 5)
	assert_almost_eq(report["median_seconds"], 300.0, 1e-6)
	assert_almost_eq(report["p10_seconds"], 140.0, 1e-6, "0.4 of the way from 100 to 200 s")
	# 3 jackpots in 3000 s of play.
	assert_almost_eq(report["jackpots_per_hour"], 3.6, 1e-6)
	assert_almost_eq(report["jackpot_payout_mean"], 350.0 / 3.0, 0.05)
	assert_eq(report["capped"], 1)


func test_a_session_ends_when_the_cup_runs_dry() -> void:
	# Classic's 25 balls: the session ends with the cup and the field empty, within the cap.
	var level: BoardLevel = load(CLASSIC)
	var session := PachinkoSessions.play(level, 1, 600.0)
	assert_false(session["capped"], "the game ended")
	assert_gte(session["shots"], level.cup_start_balls, "every start ball was fired")
	# At least one autoplay pause per shot but the first.
	var shots: int = session["shots"]
	var least := (shots - 1) * PachinkoAutoplay.MIN_GAP
	assert_gte(session["seconds"], least)
	assert_eq(session["jackpots"], 0, "classic has no reels")
	var report := PachinkoSessions.report_for(level, 2, 1, 600.0)
	assert_eq(report["sessions"], 2)
	assert_lte(report["p10_seconds"], report["median_seconds"])


func test_a_session_longer_than_the_cap_counts_as_the_cap() -> void:
	var session := PachinkoSessions.play(load(CLASSIC), 1, 3.0)
	assert_true(session["capped"])
	assert_almost_eq(session["seconds"], 3.0, 0.02)
