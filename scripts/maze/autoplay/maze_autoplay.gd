class_name MazeAutoplay
extends RefCounted
## Plays a maze board headless: a MazePilot tilts the board each physics step until every
## ball is in the goal, a ball falls into a hole, or the time runs out. Same board, seconds
## and seed → the same result, step for step.


## Plays `level` for up to `seconds` of simulated time with the pilot seeded by `rng_seed`.
## Returns won, time_to_win (-1 when not won), balls_in_goal (at the end),
## max_balls_in_goal, balls_lost_in_holes, closest_hole_gap (the least room, px, any ball's
## centre kept from a live hole's rim; -1 with no live holes), frames_simulated, hard_mode,
## state_hash.
## A `recorder` (optional) records the run for a replay.
static func run(
	level: BoardLevel,
	seconds: float,
	rng_seed: int,
	hard_mode := false,
	recorder: ReplayRecorder = null
) -> Dictionary:
	if level == null or not level.is_maze():
		push_error("MazeAutoplay: a maze board is needed")
		return {"ok": false, "error": "MazeAutoplay: a maze board is needed"}
	if not is_finite(seconds) or seconds <= 0.0:
		return {"ok": false, "error": "MazeAutoplay: seconds must be > 0, got %s" % seconds}
	var rules := MazeRules.new(level, hard_mode)
	if not rules.is_ready():
		return {"ok": false, "error": "MazeAutoplay: board '%s' did not build" % level.board_id}
	var rng := RandomNumberGenerator.new()
	rng.seed = rng_seed
	var pilot := MazePilot.new(level, hard_mode, rng, rules.step_seconds())
	if recorder != null:
		recorder.attach_maze(rules, rng_seed)
	rules.start()
	var frames := 0
	var most_in_goal := 0
	var holes := level.holes if hard_mode else PackedVector2Array()
	var closest := INF
	var limit := ceili(seconds / rules.step_seconds())
	while frames < limit and rules.is_playing():
		var world := rules.world
		closest = minf(closest, _hole_gap(world.get_positions(), holes, level.hole_radius))
		rules.set_tilt(pilot.decide(world.get_positions(), world.get_velocities()))
		rules.step()
		if recorder != null:
			recorder.note_frame()
		frames += 1
		most_in_goal = maxi(most_in_goal, rules.balls_in_goal)
	var won := rules.state == MazeRules.State.WON
	return {
		"won": won,
		"time_to_win": snappedf(rules.elapsed, 0.001) if won else -1.0,
		"balls_in_goal": rules.balls_in_goal,
		"max_balls_in_goal": most_in_goal,
		"balls_lost_in_holes": rules.balls_lost(),
		"closest_hole_gap": snappedf(closest, 0.01) if is_finite(closest) else -1.0,
		"frames_simulated": frames,
		"hard_mode": hard_mode,
		"state_hash": rules.world.state_hash(),
	}


# Least distance from a ball's centre to a hole's rim, px (INF with no holes).
static func _hole_gap(
	positions: PackedVector2Array, holes: PackedVector2Array, radius: float
) -> float:
	var gap := INF
	for p in positions:
		for h in holes:
			gap = minf(gap, p.distance_to(h) - radius)
	return gap
