extends GutTest
## The ring border: balls stay inside, ride it smoothly (the launch rail), and the gutter
## arc drains a ball after its bounces; energy never grows.

const CENTER := Vector2(500, 500)
const RING_R := 500.0
const BALL_R := 5.0


func _world(t: PhysicsTuning) -> BallWorld:
	var w := BallWorld.new(t)
	w.shapes.set_ring(CENTER, RING_R)
	return w


func _energy(w: BallWorld) -> float:
	var e := 0.0
	var pos := w.get_positions()
	var vel := w.get_velocities()
	for i: int in pos.size():
		e += 0.5 * vel[i].length_squared() - w.gravity.dot(pos[i])
	return e


func test_ball_rides_the_ring_over_the_top_without_gaining_or_losing() -> void:
	var t := TuningPresets.pachinko()
	t.min_horizontal_speed = 0.0
	t.fixed_hz = 240.0
	var w := _world(t)
	# Launched at the bottom along the tangent, fast enough to loop: sqrt(5·g·R) ≈ 1,390.
	var lim := RING_R - BALL_R
	var id := w.spawn_ball(CENTER + Vector2(0, lim), Vector2(1500, 0), BALL_R)
	var e0 := _energy(w)
	var hits := [0]
	w.ring_hit.connect(func(_b: int, _s: float) -> void: hits[0] += 1)
	var reached_top := false
	var max_gap := 0.0
	var min_y := INF
	for _i: int in 480:
		w.step(1.0 / 240.0)
		var p := w.get_ball_position(id)
		min_y = minf(min_y, p.y)
		max_gap = maxf(max_gap, lim - p.distance_to(CENTER))
		if p.y < CENTER.y - lim + 1.0:
			reached_top = true
		assert_lt(_energy(w), e0 * 1.0005 + 1.0, "no energy pumped in by the ring")
	assert_true(reached_top, "looped over the top (highest y %.1f)" % min_y)
	assert_lt(max_gap, 0.5, "kept contact with the ring all the way")
	assert_eq(hits[0], 0, "riding is not bouncing")
	assert_gt(_energy(w), e0 * 0.97, "and drained almost nothing")


func test_weak_shot_rolls_back_down() -> void:
	var t := TuningPresets.pachinko()
	var w := _world(t)
	var lim := RING_R - BALL_R
	var id := w.spawn_ball(CENTER + Vector2(0, lim), Vector2(600, 0), BALL_R)
	var max_x := 0.0
	for _i: int in 240:
		w.step(1.0 / 120.0)
		max_x = maxf(max_x, w.get_ball_position(id).x)
	assert_lt(max_x, CENTER.x + lim, "never reached the side of the ring")
	assert_lt(w.get_ball_position(id).x, max_x - 10.0, "came back")


func test_gutter_drains_after_its_bounces_exactly_once() -> void:
	var t := TuningPresets.pachinko()
	var w := _world(t)
	w.shapes.set_drain_arc(45.0, 135.0, 3, w.tuning.drain_slide_time)
	var drained: Array = []
	var rings := [0]
	w.ball_drained.connect(func(b: int) -> void: drained.append(b))
	w.ring_hit.connect(func(_b: int, _s: float) -> void: rings[0] += 1)
	var id := w.spawn_ball(CENTER + Vector2(0, 300), Vector2.ZERO, BALL_R)
	for _i: int in 600:
		w.step(1.0 / 120.0)
	assert_eq(drained, [id])
	assert_false(w.has_ball(id))
	assert_eq(rings[0], 3, "three bounces, then drained")


func test_ball_resting_in_the_gutter_still_drains() -> void:
	var t := TuningPresets.pachinko()
	var w := _world(t)
	w.shapes.set_drain_arc(45.0, 135.0, 50, w.tuning.drain_slide_time)
	var drained := [0]
	w.ball_drained.connect(func(_b: int) -> void: drained[0] += 1)
	w.spawn_ball(CENTER + Vector2(0, RING_R - BALL_R - 0.5), Vector2.ZERO, BALL_R)
	for _i: int in 240:
		w.step(1.0 / 120.0)
	assert_eq(drained[0], 1)


func test_no_ball_leaves_the_ring_in_a_long_random_run() -> void:
	var t := TuningPresets.pachinko()
	t.max_speed = 4000.0
	var w := _world(t)
	var rng := RandomNumberGenerator.new()
	rng.seed = 11
	for i: int in 150:
		var a := rng.randf() * TAU
		var p := CENTER + Vector2.from_angle(a) * rng.randf_range(0.0, 480.0)
		w.shapes.add_pin(p, 1.5)
	for _i: int in 200:
		var a := rng.randf() * TAU
		var p := CENTER + Vector2.from_angle(a) * rng.randf_range(0.0, 480.0)
		var v := Vector2.from_angle(rng.randf() * TAU) * rng.randf_range(0.0, 4000.0)
		w.spawn_ball(p, v, BALL_R)
	var escaped := 0
	for _s: int in 400:
		w.step(1.0 / 60.0)
		for p: Vector2 in w.get_positions():
			if p.distance_to(CENTER) > RING_R - BALL_R + 0.01:
				escaped += 1
	assert_eq(escaped, 0)
	assert_eq(w.ball_count(), 200)


func test_energy_never_grows_in_a_busy_board() -> void:
	var t := TuningPresets.pachinko()
	t.min_horizontal_speed = 0.0
	var w := _world(t)
	for y: int in range(150, 850, 24):
		for x: int in range(150, 850, 24):
			var p := Vector2(x + (12 if (y / 24) % 2 == 1 else 0), y)
			if p.distance_to(CENTER) < 440.0:
				w.shapes.add_pin(p, 1.5)
	var rng := RandomNumberGenerator.new()
	rng.seed = 3
	for _i: int in 150:
		var p := Vector2(rng.randf_range(300, 700), rng.randf_range(40, 140))
		w.spawn_ball(p, Vector2(rng.randf_range(-100, 100), 0), BALL_R)
	var e_prev := _energy(w)
	for s: int in 480:
		w.step(1.0 / 120.0)
		if s % 24 == 23:
			var e := _energy(w)
			# Per-ball slack of 1 px²/s² for float error.
			assert_lt(e, e_prev + w.ball_count() * 1.0, "energy at step %d" % s)
			e_prev = e


func test_a_drain_arc_drains_a_resting_ball_after_its_own_slide_time() -> void:
	for slide_time: float in [0.25, 1.0]:
		var w := _world(TuningPresets.pachinko())
		w.shapes.set_drain_arc(45.0, 135.0, 50, slide_time)
		var drained_at := [-1]
		w.ball_drained.connect(func(_b: int) -> void: drained_at[0] = w.step_count)
		w.spawn_ball(CENTER + Vector2(0, RING_R - BALL_R - 0.5), Vector2.ZERO, BALL_R)
		for _i: int in 240:
			w.step(1.0 / 120.0)
		assert_gt(drained_at[0], 0, "drained (slide time %s)" % slide_time)
		assert_lte(drained_at[0] / 120.0, slide_time + 0.1, "not later than its slide time")
		assert_gte(drained_at[0] / 120.0, slide_time - 0.1, "not sooner")


func test_a_drain_arc_with_bad_numbers_is_refused() -> void:
	var w := _world(TuningPresets.pachinko())
	w.shapes.set_drain_arc(45.0, NAN, 3, 0.5)
	w.shapes.set_drain_arc(45.0, 135.0, 0, 0.5)
	w.shapes.set_drain_arc(45.0, 135.0, 3, -1.0)
	assert_push_error_count(3, "each bad call names its problem")
	w.spawn_ball(CENTER + Vector2(0, RING_R - BALL_R - 0.5), Vector2.ZERO, BALL_R)
	for _i: int in 120:
		w.step(1.0 / 120.0)
	assert_eq(w.ball_count(), 1, "no arc was set, so nothing drains")


## Seed fidelity: the Flash chapter resolves a ring hit as it does a pin hit, minimum
## horizontal speed included, so a ball dropped straight onto the bottom of the ring does
## not bounce on the spot forever.
func test_a_ring_hit_leaves_the_ball_the_rings_least_horizontal_speed() -> void:
	var t := TuningPresets.pachinko()
	var least: float = t.min_horizontal_speed
	var w := BallWorld.new(t)
	w.shapes.set_ring(CENTER, RING_R, least)
	var id := w.spawn_ball(CENTER + Vector2(0.0, RING_R - 60.0), Vector2.ZERO, BALL_R)
	var hit := [false]
	w.ring_hit.connect(func(_b: int, _s: float) -> void: hit[0] = true)
	while not hit[0] and w.step_count < 240:
		w.step(1.0 / 120.0)
	assert_true(hit[0], "the ball reached the ring")
	assert_almost_eq(absf(w.get_ball_velocity(id).x), least, 1e-3)


func test_a_ring_without_the_material_leaves_a_straight_drop_straight() -> void:
	var w := BallWorld.new(TuningPresets.pachinko())
	w.shapes.set_ring(CENTER, RING_R)
	var id := w.spawn_ball(CENTER + Vector2(0.0, RING_R - 60.0), Vector2.ZERO, BALL_R)
	for _i: int in 60:
		w.step(1.0 / 120.0)
	assert_eq(w.get_ball_velocity(id).x, 0.0)
