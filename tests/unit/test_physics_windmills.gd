extends GutTest
## Windmills (BallWorld.add_windmill): kinematic wheels of capsule blades. A ball never
## passes through a blade at any blade or ball speed up to the top speed; a moving blade
## throws a ball; a free wheel is spun by the balls that strike it and slowed by its
## friction; 1, 2 and 4 threads give the same world.

const DT := 1.0 / 120.0
const BALL_R := 5.0
const BLADE_R := 2.0
const LENGTH := 30.0


func _empty_world() -> BallWorld:
	var t := TuningPresets.pachinko()
	var w := BallWorld.new(t)
	w.gravity = Vector2.ZERO
	return w


## A two-blade bar (along x at the start) turning at `tip_speed` px/s at its tips (driven,
## either way), and one ball between its blades, `radius` px above the pin, fired at
## `ball_speed` at the point `radius` px out along the bar. Returns the worst thing seen at
## every substep: "crossed" (the ball got from one side of a blade to the other within its
## length) and "depth" (the deepest its centre was inside a blade's grown capsule, px).
func _fire_at_bar(tip_speed: float, ball_speed: float, radius: float) -> Dictionary:
	var w := _empty_world()
	var omega: float = tip_speed / (LENGTH + BLADE_R)
	w.shapes.add_windmill(Vector2.ZERO, 2, LENGTH, BLADE_R, omega)
	w.build_grid()
	var aim := Vector2(1.0, 1.0).normalized()
	w.spawn_ball(Vector2(0.0, -radius), aim * ball_speed, BALL_R)
	w.set_path_recording(true)
	var worst := {"crossed": false, "depth": 0.0}
	var prev := w.get_ball_position(0)
	var prev_turn: float = w.shapes.get_windmill_angle(0)
	for _step: int in 30:
		var turn0: float = w.shapes.get_windmill_angle(0)
		var w0: float = w.shapes.get_windmill_speed(0)
		w.step(DT)
		var points: PackedVector2Array = w.take_step_paths()["points"]
		points.append(w.get_ball_position(0))
		var n: int = points.size()
		for j: int in n:
			var turn: float = turn0 + w0 * DT * float(j + 1) / float(n)
			_look(points[j], turn, prev, prev_turn, worst)
			prev = points[j]
			prev_turn = turn
	return worst


# Notes how deep `p` is in the bar at angle `turn`, and whether the move from `prev` (bar
# at `prev_turn`) crossed it inside its length.
func _look(p: Vector2, turn: float, prev: Vector2, prev_turn: float, worst: Dictionary) -> void:
	var dir := Vector2.from_angle(turn)
	var along: float = p.dot(dir)
	var across: float = dir.cross(p)
	var q: Vector2 = dir * clampf(along, -LENGTH, LENGTH)
	var depth: float = (BLADE_R + BALL_R) - p.distance_to(q)
	worst["depth"] = maxf(worst["depth"], depth)
	var prev_dir := Vector2.from_angle(prev_turn)
	var prev_along: float = prev.dot(prev_dir)
	var prev_across: float = prev_dir.cross(prev)
	var inside_span: bool = absf(along) < LENGTH and absf(prev_along) < LENGTH
	if inside_span and signf(across) != signf(prev_across) and across != 0.0:
		worst["crossed"] = true


func test_a_ball_fired_at_a_blade_never_passes_through_or_ends_inside_it() -> void:
	var top: float = TuningPresets.pachinko().max_speed
	var failures := PackedStringArray()
	for tip_step: int in range(-4, 5):
		var tip_speed: float = top * tip_step / 4.0
		for ball_step: int in 9:
			var ball_speed: float = top * ball_step / 8.0
			for radius: float in [12.0, 20.0, 27.0]:
				var seen := _fire_at_bar(tip_speed, ball_speed, radius)
				var depth: float = seen["depth"]
				if seen["crossed"] or depth > 0.05:
					var what := "tip %d px/s, ball %d px/s, %d px out: crossed %s, depth %.2f px"
					failures.append(what % [tip_speed, ball_speed, radius, seen["crossed"], depth])
	assert_eq(failures, PackedStringArray(), "no ball gets into or through a blade")


func test_a_moving_blade_throws_a_ball_it_strikes() -> void:
	var w := _empty_world()
	# Turning clockwise on screen: the blade along +x sweeps down (+y) at its tip.
	w.shapes.add_windmill(Vector2.ZERO, 2, LENGTH, BLADE_R, 20.0)
	w.build_grid()
	var id := w.spawn_ball(Vector2(24.0, 14.0), Vector2.ZERO, BALL_R)
	for _i: int in 6:
		w.step(DT)
	var v := w.get_ball_velocity(id)
	assert_gt(v.length(), 200.0, "the ball was thrown, not just pushed aside")


func test_a_driven_wheel_keeps_its_speed_when_struck() -> void:
	var w := _empty_world()
	w.shapes.add_windmill(Vector2.ZERO, 4, LENGTH, BLADE_R, 3.0)
	w.build_grid()
	w.spawn_ball(Vector2(20.0, -60.0), Vector2(0.0, 900.0), BALL_R)
	for _i: int in 60:
		w.step(DT)
	assert_eq(w.shapes.get_windmill_speed(0), 3.0)
	assert_almost_eq(w.shapes.get_windmill_angle(0), fposmod(3.0 * 60.0 * DT, TAU), 1e-9)


func test_a_struck_free_wheel_speeds_up_then_slows_by_its_friction() -> void:
	var w := _empty_world()
	var friction := 6.0
	w.shapes.add_windmill(Vector2.ZERO, 4, LENGTH, BLADE_R, 0.0, true, friction)
	w.build_grid()
	# The ball comes down right of the pin onto the blade along +x: clockwise on screen.
	var id := w.spawn_ball(Vector2(24.0, -60.0), Vector2(0.0, 1200.0), BALL_R)
	var speeds := PackedFloat64Array()
	for _i: int in 600:
		w.step(DT)
		speeds.append(w.shapes.get_windmill_speed(0))
		if w.has_ball(id) and w.get_ball_position(id).length() > 120.0:
			w.remove_ball(id)
	var peak: float = speeds[0]
	var peak_at := 0
	for k: int in speeds.size():
		if speeds[k] > peak:
			peak = speeds[k]
			peak_at = k
	assert_gt(peak, 1.0, "the strike spun the wheel clockwise")
	# After the ball is gone, each step takes exactly friction * dt off, down to rest.
	var last := speeds.size() - 1
	assert_eq(speeds[last], 0.0, "friction brought it to rest")
	var slowing := 0
	for k: int in range(peak_at + 1, last):
		if speeds[k] > 0.0 and speeds[k - 1] > speeds[k]:
			assert_almost_eq(speeds[k - 1] - speeds[k], friction * DT, 1e-9)
			slowing += 1
	assert_gt(slowing, 10, "it slowed step by step")
	var stopped_at: int = speeds.find(0.0, peak_at)
	var seconds: float = float(stopped_at - peak_at) * DT
	assert_almost_eq(seconds, peak / friction, 0.1, "stopped when its friction says it would")


func test_a_free_wheel_is_held_to_the_top_tip_speed() -> void:
	var w := _empty_world()
	w.shapes.add_windmill(Vector2.ZERO, 3, LENGTH, BLADE_R, 1e6, true, 0.0)
	w.build_grid()
	var cap: float = w.tuning.max_speed / (LENGTH + BLADE_R)
	assert_almost_eq(w.shapes.get_windmill_speed(0), cap, 1e-9)


func test_bad_windmills_are_refused_with_an_error() -> void:
	var w := _empty_world()
	assert_eq(w.shapes.add_windmill(Vector2.ZERO, 0, LENGTH, BLADE_R, 1.0), -1)
	assert_eq(w.shapes.add_windmill(Vector2(NAN, 0.0), 3, LENGTH, BLADE_R, 1.0), -1)
	assert_eq(w.shapes.add_windmill(Vector2.ZERO, 3, -1.0, BLADE_R, 1.0), -1)
	assert_eq(w.shapes.add_windmill(Vector2.ZERO, 3, LENGTH, BLADE_R, 1.0, true, -2.0), -1)
	assert_eq(w.shapes.windmill_count(), 0)
	assert_push_error_count(4)


## Pins, a ring and windmills (driven and free) under a rain of balls.
func _windmill_world(threads: int) -> BallWorld:
	var w := BallWorld.new(TuningPresets.pachinko())
	w.threads = threads
	w.shapes.set_ring(Vector2.ZERO, 220.0)
	w.shapes.set_drain_arc(60.0, 120.0, 3, w.tuning.drain_slide_time)
	var rng := RandomNumberGenerator.new()
	rng.seed = 5
	for _i: int in 80:
		w.shapes.add_pin(Vector2(rng.randf_range(-150, 150), rng.randf_range(-40, 120)), 1.5)
	w.shapes.add_windmill(Vector2(-80, -60), 4, 24.0, 2.0, 4.0)
	w.shapes.add_windmill(Vector2(0, -40), 3, 28.0, 2.0, 0.0, true, 3.0)
	w.shapes.add_windmill(Vector2(90, -60), 6, 22.0, 2.0, -6.0)
	w.shapes.add_windmill(Vector2(40, 40), 4, 20.0, 2.0, 0.0, true, 1.0)
	w.build_grid()
	for _i: int in 300:
		var p := Vector2(rng.randf_range(-120, 120), rng.randf_range(-200, -110))
		w.spawn_ball(p, Vector2(rng.randf_range(-200, 200), 0), 4.0)
	return w


func test_windmill_world_is_bit_identical_for_1_2_and_4_threads() -> void:
	var hashes: Array[int] = []
	var hits: Array = []
	for threads: int in [1, 2, 4]:
		var w := _windmill_world(threads)
		var log: Array = []
		w.windmill_hit.connect(func(b: int, m: int, s: float) -> void: log.append([b, m, s]))
		for _i: int in 240:
			w.step(DT)
		hashes.append(w.state_hash())
		hits.append(log)
		if threads == 1:
			assert_gt(log.size(), 20, "balls struck the blades")
			assert_ne(w.shapes.get_windmill_speed(1), 0.0, "the balls spun the free wheel")
	assert_eq(hashes[1], hashes[0])
	assert_eq(hashes[2], hashes[0])
	assert_eq(hits[1], hits[0])
	assert_eq(hits[2], hits[0])


func test_a_ball_never_rests_on_a_blade_with_the_boards_least_sideways_speed() -> void:
	var w := BallWorld.new(TuningPresets.pachinko())
	var least: float = w.tuning.min_horizontal_speed
	# A wheel held still with blade 0 flat along +x: a ball dropped on it would lie there.
	w.shapes.add_windmill(Vector2.ZERO, 4, LENGTH, BLADE_R, 0.0, false, 0.0, least)
	w.build_grid()
	var id := w.spawn_ball(Vector2(14.0, -60.0), Vector2.ZERO, BALL_R)
	for _i: int in 360:
		w.step(DT)
	var p := w.get_ball_position(id)
	assert_true(p.y > 0.0 or absf(p.x) > LENGTH + BALL_R, "the ball rolled off, at %s" % p)
