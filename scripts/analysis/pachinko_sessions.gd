class_name PachinkoSessions
extends RefCounted
## How long a pachinko session lasts and what its jackpots bring (the `--sessions=N` command
## is scripts/app/sessions_cli.gd): plays N
## games from a full cup to an empty one with the real rules, at the autoplay's single-shot
## pace (a random power, then a pause of MIN_GAP to MAX_GAP seconds), one seed per game, and
## reports the median and 10th percentile of their lengths, jackpots per hour of play and
## what a jackpot paid on average. Same board, N and seed: the same report.

## The longest a session is played, game seconds: one still going then counts as this long
## (and as `capped` in the report), so a lucky streak cannot run forever.
const MAX_SESSION_SECONDS := 1800.0


## Plays `count` sessions on `level` with seeds `first_seed`, `first_seed` + 1, ... and
## summarises them (see summarize()), with the machine's goal_tray (PachinkoGoals, 0: none)
## and goal_clear_rate (the share of the sessions that reached it).
static func report_for(
	level: BoardLevel, count: int, first_seed: int, most_seconds := MAX_SESSION_SECONDS
) -> Dictionary:
	var sessions: Array[Dictionary] = []
	for i in count:
		sessions.append(play(level, first_seed + i, most_seconds))
	var report := summarize(sessions)
	# the machine's goal (PachinkoGoals) and the share of these sessions that reached it
	var target := PachinkoGoals.tray_target(level)
	report["goal_tray"] = target
	if target > 0:
		report["goal_clear_rate"] = clear_rate(sessions, target - level.cup_start_balls)
	return report


## One session on `level`: a fresh game from the board's start balls, fired at the
## autoplay's pace until the game is over or `most_seconds` have passed. Returns seconds,
## shots, balls_won (paid back), peak_won (the most balls held above the start),
## jackpots, jackpot_payouts (per finished jackpot; one still
## under way at the end counts what it paid so far) and capped.
static func play(
	level: BoardLevel, rng_seed: int, most_seconds := MAX_SESSION_SECONDS
) -> Dictionary:
	var rng := RandomNumberGenerator.new()
	rng.seed = rng_seed
	var rules := PachinkoRules.new(level, rng_seed)
	var cup_peak := CupPeak.new(rules)
	var payouts: Array[int] = []
	rules.bonus.jackpot_ended.connect(func(paid: int) -> void: payouts.append(paid))
	rules.start_game()
	var clock := 0.0
	var next_shot := 0.0
	var frame := PachinkoAutoplay.FRAME_SECONDS
	while rules.state == PachinkoRules.State.PLAYING and clock < most_seconds:
		clock += frame
		if rules.loaded and clock >= next_shot:
			rules.fire(rng.randf_range(0.0, 100.0))
			next_shot = clock + rng.randf_range(PachinkoAutoplay.MIN_GAP, PachinkoAutoplay.MAX_GAP)
		rules.advance(frame)
	if rules.bonus.rounds.active():
		payouts.append(rules.bonus.rounds.paid)
	var stats := rules.stats()
	return {
		"seconds": clock,
		"shots": stats["shots"],
		"balls_won": stats["payouts"],
		"peak_won": cup_peak.won(),
		"jackpots": stats["jackpots"],
		"jackpot_payouts": payouts,
		"capped": rules.state == PachinkoRules.State.PLAYING,
	}


## The report over `sessions` (play() results): sessions, median_seconds, p10_seconds,
## capped (sessions still going at the cap), jackpots, jackpots_per_hour (over all the
## seconds played), jackpot_payout_mean (balls a jackpot paid, 0 with none),
## median_balls_won and peak_won (peak_spread).
static func summarize(sessions: Array[Dictionary]) -> Dictionary:
	var seconds := PackedFloat64Array()
	var won := PackedFloat64Array()
	var peaks := PackedFloat64Array()
	var played := 0.0
	var jackpots := 0
	var capped := 0
	var payouts: Array[int] = []
	for session in sessions:
		var session_seconds: float = session["seconds"]
		var session_won: float = session["balls_won"]
		var session_jackpots: int = session["jackpots"]
		var session_payouts: Array = session["jackpot_payouts"]
		seconds.append(session_seconds)
		won.append(session_won)
		var session_peak: int = session.get("peak_won", 0)
		peaks.append(session_peak)
		played += session_seconds
		jackpots += session_jackpots
		capped += 1 if session["capped"] else 0
		payouts.append_array(session_payouts)
	var paid := 0
	for balls in payouts:
		paid += balls
	return {
		"sessions": sessions.size(),
		"median_seconds": snappedf(percentile(seconds, 0.5), 0.1),
		"p10_seconds": snappedf(percentile(seconds, 0.1), 0.1),
		"capped": capped,
		"jackpots": jackpots,
		"jackpots_per_hour": snappedf(jackpots * 3600.0 / played, 0.01) if played > 0.0 else 0.0,
		"jackpot_payout_mean":
		snappedf(float(paid) / payouts.size(), 0.1) if not payouts.is_empty() else 0.0,
		"median_balls_won": percentile(won, 0.5),
		"peak_won": peak_spread(peaks),
	}


## How the sessions' peak_won (balls held above the start at most) spread: the 50th, 60th,
## 70th and 75th percentiles, and every session's, sorted. A machine's goal (PachinkoGoals)
## is set between the 60th and 75th, so the autoplay reaches it in 25 to 40 % of sessions.
static func peak_spread(peaks: PackedFloat64Array) -> Dictionary:
	var sorted := peaks.duplicate()
	sorted.sort()
	var all: Array[int] = []
	for value in sorted:
		all.append(int(value))
	return {
		"p50": percentile(peaks, 0.5),
		"p60": percentile(peaks, 0.6),
		"p70": percentile(peaks, 0.7),
		"p75": percentile(peaks, 0.75),
		"all": all,
	}


## The share (0..1) of `sessions` (play() results) whose peak_won reached `target`.
static func clear_rate(sessions: Array[Dictionary], target: int) -> float:
	if sessions.is_empty():
		return 0.0
	var reached := 0
	for session in sessions:
		var peak: int = session.get("peak_won", 0)
		reached += 1 if peak >= target else 0
	return float(reached) / sessions.size()


## The `share` (0..1) percentile of `values`, between the nearest ranks as a spreadsheet's
## PERCENTILE does (0 for no values).
static func percentile(values: PackedFloat64Array, share: float) -> float:
	if values.is_empty():
		return 0.0
	var sorted := values.duplicate()
	sorted.sort()
	var at := clampf(share, 0.0, 1.0) * (sorted.size() - 1)
	var below := floori(at)
	var above := mini(below + 1, sorted.size() - 1)
	return lerpf(sorted[below], sorted[above], at - below)
