extends GutTest
## Determinism (same inputs → bit-identical state) and degenerate input: no NaN, no crash,
## bad arguments refused with an error that names the problem.


func _busy_world(seed_value: int) -> BallWorld:
	var w := BallWorld.new(TuningPresets.pachinko())
	w.shapes.set_ring(Vector2(0, 0), 200.0)
	w.shapes.set_drain_arc(60.0, 120.0, 3, w.tuning.drain_slide_time)
	w.shapes.add_wall(Vector2(-150, 50), Vector2(-20, 90), 3.0)
	var rng := RandomNumberGenerator.new()
	rng.seed = seed_value
	for _i: int in 80:
		w.shapes.add_pin(Vector2(rng.randf_range(-150, 150), rng.randf_range(-120, 120)), 1.5)
	w.build_grid()
	for _i: int in 120:
		var p := Vector2(rng.randf_range(-100, 100), rng.randf_range(-180, -120))
		w.spawn_ball(p, Vector2(rng.randf_range(-200, 200), 0), 5.0)
	return w


func test_same_inputs_give_bit_identical_state() -> void:
	var a := _busy_world(42)
	var b := _busy_world(42)
	for _i: int in 300:
		a.advance(1.0 / 60.0)
		b.advance(1.0 / 60.0)
	assert_eq(a.step_count, b.step_count)
	assert_eq(a.state_hash(), b.state_hash())
	assert_eq(a.get_positions(), b.get_positions())
	assert_eq(a.get_velocities(), b.get_velocities())


func test_different_inputs_differ() -> void:
	var a := _busy_world(42)
	var b := _busy_world(43)
	for _i: int in 30:
		a.step(1.0 / 120.0)
		b.step(1.0 / 120.0)
	assert_ne(a.state_hash(), b.state_hash())


func test_advance_runs_whole_fixed_steps() -> void:
	var w := BallWorld.new(TuningPresets.pachinko())
	w.tuning.fixed_hz = 100.0
	assert_eq(w.advance(0.025), 2)
	assert_eq(w.advance(0.005), 1, "the remainder carried over")
	assert_eq(w.step_count, 3)
	assert_eq(w.advance(10.0), BallWorld.MAX_STEPS_PER_ADVANCE, "a hitch is capped")


func test_ball_exactly_on_a_pin_centre_is_pushed_out() -> void:
	var w := BallWorld.new(TuningPresets.pachinko())
	w.shapes.add_pin(Vector2(10, 10), 1.5)
	var id := w.spawn_ball(Vector2(10, 10), Vector2.ZERO, 5.0)
	for _i: int in 30:
		w.step(1.0 / 120.0)
	var p := w.get_ball_position(id)
	assert_true(p.is_finite() and w.get_ball_velocity(id).is_finite())
	assert_gt(p.distance_to(Vector2(10, 10)), 6.4)


func test_ball_exactly_on_a_wall_segment_is_pushed_out() -> void:
	var w := BallWorld.new(TuningPresets.maze())
	w.shapes.add_wall(Vector2(0, 0), Vector2(100, 0), 5.0)
	var id := w.spawn_ball(Vector2(50, 0), Vector2.ZERO, 5.0)
	w.step(1.0 / 120.0)
	var p := w.get_ball_position(id)
	assert_true(p.is_finite())
	assert_almost_eq(absf(p.y), 10.0, 0.001)


func test_zero_length_wall_and_zero_radius_pin_are_fine() -> void:
	var w := BallWorld.new(TuningPresets.maze())
	assert_eq(w.shapes.add_wall(Vector2(5, 5), Vector2(5, 5), 0.0), 0)
	assert_eq(w.shapes.add_pin(Vector2(50, 5), 0.0), 0)
	var a := w.spawn_ball(Vector2(5, 5), Vector2(10, 0), 5.0)
	var b := w.spawn_ball(Vector2(50, 5), Vector2(0, 10), 5.0)
	for _i: int in 60:
		w.step(1.0 / 120.0)
	assert_true(w.get_ball_position(a).is_finite() and w.get_ball_position(b).is_finite())


func test_bad_radius_is_refused_with_a_clear_error() -> void:
	var w := BallWorld.new()
	assert_eq(w.spawn_ball(Vector2.ZERO, Vector2.ZERO, 0.0), -1)
	assert_push_error("radius > 0")
	assert_eq(w.spawn_ball(Vector2.ZERO, Vector2.ZERO, -3.0), -1)
	assert_push_error("radius > 0")
	assert_eq(w.spawn_ball(Vector2(NAN, 0), Vector2.ZERO, 5.0), -1)
	assert_push_error("finite")
	assert_eq(w.spawn_ball(Vector2.ZERO, Vector2(INF, 0), 5.0), -1)
	assert_push_error("finite")
	assert_eq(w.shapes.add_pin(Vector2.ZERO, -1.0), -1)
	assert_push_error("radius >= 0")
	assert_eq(w.shapes.add_wall(Vector2.ZERO, Vector2.ONE, -1.0), -1)
	assert_push_error("radius >= 0")
	assert_eq(w.shapes.add_hole(Vector2.ZERO, 0.0), -1)
	assert_push_error("add_hole")
	assert_eq(w.ball_count(), 0)


func test_bad_step_and_gravity_do_not_poison_the_state() -> void:
	var w := BallWorld.new()
	var id := w.spawn_ball(Vector2.ZERO, Vector2.ZERO, 5.0)
	w.step(0.0)
	assert_push_error("dt must be")
	w.gravity = Vector2(NAN, 0)
	w.step(1.0 / 120.0)
	assert_push_error("gravity must be finite")
	assert_true(w.get_ball_position(id).is_finite())


func test_removed_ids_stay_gone_and_are_not_reused() -> void:
	var w := BallWorld.new()
	var a := w.spawn_ball(Vector2.ZERO, Vector2.ZERO, 5.0)
	var b := w.spawn_ball(Vector2(20, 0), Vector2.ZERO, 5.0)
	w.remove_ball(a)
	var c := w.spawn_ball(Vector2(40, 0), Vector2.ZERO, 5.0)
	assert_false(w.has_ball(a))
	assert_ne(c, a)
	assert_eq(w.get_ids(), PackedInt32Array([b, c]))
	assert_eq(w.get_ball_position(c), Vector2(40, 0))
	w.remove_ball(12345)
	assert_eq(w.ball_count(), 2)


func test_removing_several_balls_at_once_leaves_the_world_one_by_one_leaves() -> void:
	var worlds: Array[BallWorld] = []
	for k in 2:
		var w := BallWorld.new(TuningPresets.pachinko())
		w.shapes.set_ring(Vector2.ZERO, 200.0)
		for i in 8:
			w.spawn_ball(Vector2(i * 12 - 48, i * 5), Vector2(i * 10, -i * 7), 5.0)
		for _i: int in 30:
			w.step(1.0 / 120.0)
		worlds.append(w)
	var gone := PackedInt32Array([6, 1, 4, 77])
	for id: int in gone:
		worlds[0].remove_ball(id)
	worlds[1].remove_balls(gone)
	assert_eq(worlds[1].get_ids(), PackedInt32Array([0, 2, 3, 5, 7]))
	for _i: int in 60:
		for w: BallWorld in worlds:
			w.step(1.0 / 120.0)
	assert_eq(worlds[1].state_hash(), worlds[0].state_hash(), "the same world after")


## A handler that steps the world from inside the step's own signal would run a step inside
## a half-done one: it is refused with an error, and the outer step finishes as usual.
func test_a_step_from_inside_a_steps_signal_is_refused() -> void:
	var w := BallWorld.new(TuningPresets.pachinko())
	w.shapes.set_ring(Vector2.ZERO, 100.0)
	w.spawn_ball(Vector2(0, 80), Vector2(0, 400), 5.0)
	var inner := [0]
	var step_inside := func(_ball: int, _speed: float) -> void:
		inner[0] = w.step_count
		w.step(1.0 / 120.0)
	w.ring_hit.connect(step_inside)
	for _i: int in 10:
		w.step(1.0 / 120.0)
	assert_gt(inner[0], 0, "the ball hit the ring and the handler tried to step")
	assert_eq(w.step_count, 10, "only the outer steps ran")
	assert_push_error("called from a handler of this world's own signal")
