extends GutTest
## Ball-ball contacts: equal masses, restitution on the normal, momentum conserved, and no
## NaN when two balls share a point.


func _free_world(e: float) -> BallWorld:
	var t := TuningPresets.pachinko()
	t.gravity = Vector2.ZERO
	t.ball_restitution = e
	t.min_horizontal_speed = 0.0
	t.max_speed = 10000.0
	return BallWorld.new(t)


func _momentum(w: BallWorld) -> Vector2:
	var m := Vector2.ZERO
	for v: Vector2 in w.get_velocities():
		m += v
	return m


func test_head_on_equal_masses_swap_with_restitution() -> void:
	var w := _free_world(1.0)
	var a := w.spawn_ball(Vector2(0, 0), Vector2(200, 0), 5.0)
	var b := w.spawn_ball(Vector2(40, 0), Vector2.ZERO, 5.0)
	for _i: int in 120:
		w.step(1.0 / 240.0)
	assert_almost_eq(w.get_ball_velocity(a).x, 0.0, 0.01, "elastic: the mover stops")
	assert_almost_eq(w.get_ball_velocity(b).x, 200.0, 0.01, "and the other takes its speed")


func test_restitution_scales_the_normal_relative_speed() -> void:
	var w := _free_world(0.6)
	var a := w.spawn_ball(Vector2(0, 0), Vector2(100, 0), 5.0)
	var b := w.spawn_ball(Vector2(40, 0), Vector2(-100, 0), 5.0)
	for _i: int in 120:
		w.step(1.0 / 240.0)
	var rel := w.get_ball_velocity(b).x - w.get_ball_velocity(a).x
	assert_almost_eq(rel, 0.6 * 200.0, 0.01)


func test_momentum_is_conserved_in_a_crowd() -> void:
	var w := _free_world(0.6)
	# The contact law alone: a sleeping ball holds still against slow touches (see
	# test_physics_sleep.gd), which is not momentum-conserving by design.
	w.tuning.sleep_time = 0.0
	var rng := RandomNumberGenerator.new()
	rng.seed = 5
	for _i: int in 300:
		var p := Vector2(rng.randf_range(0, 200), rng.randf_range(0, 200))
		w.spawn_ball(p, Vector2(rng.randf_range(-300, 300), rng.randf_range(-300, 300)), 5.0)
	var m0 := _momentum(w)
	var contacts := 0
	for _i: int in 120:
		var before := w.get_velocities().duplicate()
		w.step(1.0 / 240.0)
		if before != w.get_velocities():
			contacts += 1
	var m1 := _momentum(w)
	assert_gt(contacts, 10, "the balls did collide")
	assert_almost_eq(m1.x, m0.x, 0.05)
	assert_almost_eq(m1.y, m0.y, 0.05)


func test_two_balls_on_one_point_separate_without_nan() -> void:
	var w := _free_world(0.6)
	var a := w.spawn_ball(Vector2(10, 10), Vector2.ZERO, 5.0)
	var b := w.spawn_ball(Vector2(10, 10), Vector2.ZERO, 5.0)
	for _i: int in 60:
		w.step(1.0 / 240.0)
	var pa := w.get_ball_position(a)
	var pb := w.get_ball_position(b)
	assert_true(pa.is_finite() and pb.is_finite())
	assert_true(w.get_ball_velocity(a).is_finite())
	assert_gt(pa.distance_to(pb), 9.0, "pushed apart")


func test_pile_in_the_ring_loses_energy_and_stays_inside() -> void:
	var t := TuningPresets.pachinko()
	var w := BallWorld.new(t)
	w.shapes.set_ring(Vector2(0, 0), 100.0)
	var rng := RandomNumberGenerator.new()
	rng.seed = 9
	for _i: int in 80:
		w.spawn_ball(Vector2(rng.randf_range(-60, 60), rng.randf_range(-60, 20)), Vector2.ZERO, 5.0)
	var e0 := _total_energy(w)
	for _i: int in 600:
		w.step(1.0 / 120.0)
	assert_lt(_total_energy(w), e0, "a falling pile only loses energy")
	for p: Vector2 in w.get_positions():
		assert_lt(p.length(), 95.01, "inside the ring")


func _total_energy(w: BallWorld) -> float:
	var e := 0.0
	var pos := w.get_positions()
	var vel := w.get_velocities()
	for i: int in pos.size():
		e += 0.5 * vel[i].length_squared() - w.gravity.dot(pos[i])
	return e
