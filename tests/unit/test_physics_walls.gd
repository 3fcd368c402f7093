extends GutTest
## BallWorld against capsule walls: the maze's 1/3 bounce, sliding, rolling round a cap with
## no snag and no lost speed, smooth joints, and no ball ever crossing a wall.

const HZ := 120.0


func _maze_world() -> BallWorld:
	var t := TuningPresets.maze()
	t.rolling_friction = 0.0
	return BallWorld.new(t)


func test_wall_bounce_keeps_a_third_of_the_normal_speed() -> void:
	var w := _maze_world()
	w.shapes.add_wall(Vector2(-100, 0), Vector2(100, 0), 5.0)
	var id := w.spawn_ball(Vector2(0, -40), Vector2(30, 80), 5.0)
	var hits: Array = []
	w.wall_hit.connect(func(b: int, i: int, s: float) -> void: hits.append([b, i, s]))
	for _i: int in 60:
		w.step(1.0 / HZ)
	var v := w.get_ball_velocity(id)
	assert_almost_eq(v.y, -80.0 / 3.0, 0.01, "80 px/s in, a third of it out")
	assert_almost_eq(v.x, 30.0, 0.01, "maze walls keep the tangential speed")
	assert_eq(hits.size(), 1)
	assert_almost_eq(float(hits[0][2]), 80.0, 0.01)


func test_ball_slides_along_a_wall_without_losing_speed() -> void:
	var w := _maze_world()
	w.gravity = Vector2(0, 1600)
	w.shapes.add_wall(Vector2(-500, 0), Vector2(500, 0), 5.0)
	var id := w.spawn_ball(Vector2(-400, -10), Vector2(80, 0), 5.0)
	for _i: int in 240:
		w.step(1.0 / HZ)
	var p := w.get_ball_position(id)
	assert_almost_eq(p.y, -10.0, 0.001, "rests on the wall, no jitter")
	assert_almost_eq(w.get_ball_velocity(id).x, 80.0, 0.001)
	assert_almost_eq(p.x, -400.0 + 160.0, 0.01)


func test_ball_rolls_round_a_cap_keeping_contact_and_energy() -> void:
	var w := _maze_world()
	var g := 1600.0
	# The ball slides along the top of a wall, reaches its end and rolls over the cap.
	w.gravity = Vector2(0, g)
	w.tuning.max_speed = 10000.0
	var cap := Vector2(0, 0)
	w.shapes.add_wall(Vector2(-200, 0), cap, 5.0)
	var v0 := 90.0
	var id := w.spawn_ball(Vector2(-100, -10), Vector2(v0, 0), 5.0)
	var max_gap := 0.0
	var left := false
	var left_at := 0.0
	for _i: int in 600:
		w.step(1.0 / 480.0)
		var p := w.get_ball_position(id)
		if p.x <= 0.0:
			continue
		var gap := p.distance_to(cap) - 10.0
		if not left and gap > 0.05:
			left = true
			left_at = atan2(p.y - cap.y, p.x - cap.x)
		if not left:
			max_gap = maxf(max_gap, gap)
			# Energy: v² = v0² + 2·g·drop, with no friction in this tuning.
			var drop := p.y - (-10.0)
			var expect := sqrt(v0 * v0 + 2.0 * g * drop)
			var speed := w.get_ball_velocity(id).length()
			assert_almost_eq(speed, expect, expect * 0.03 + 1.0, "speed on the cap")
	# Leaving angle from the top: cos φ = (v0² / (g·ρ) + 2) / 3 for a ball on a circle.
	var rho := 10.0
	var phi := acos(clampf((v0 * v0 / (g * rho) + 2.0) / 3.0, -1.0, 1.0))
	assert_gt(left_at, -PI / 2.0 + phi - 0.25, "kept contact round the cap")
	assert_lt(max_gap, 0.05)


func test_collinear_joint_has_no_ghost_bump() -> void:
	var w := _maze_world()
	w.gravity = Vector2(0, 1600)
	for k: int in 10:
		w.shapes.add_wall(Vector2(-500 + k * 35, 0), Vector2(-465 + k * 35, 0), 5.0)
	var id := w.spawn_ball(Vector2(-480, -10), Vector2(90, 0), 5.0)
	var hits := [0]
	w.wall_hit.connect(func(_b: int, _i: int, _s: float) -> void: hits[0] += 1)
	for _i: int in 300:
		w.step(1.0 / HZ)
		assert_almost_eq(w.get_ball_position(id).y, -10.0, 0.001, "flat over the joints")
	assert_almost_eq(w.get_ball_velocity(id).x, 90.0, 0.001)
	assert_eq(hits[0], 0, "no hit at a joint")


func test_zero_length_wall_is_a_round_post() -> void:
	var w := _maze_world()
	var wall := w.shapes.add_wall(Vector2(0, 0), Vector2(0, 0), 5.0)
	assert_eq(wall, 0)
	var id := w.spawn_ball(Vector2(0, -40), Vector2(0, 90), 5.0)
	for _i: int in 60:
		w.step(1.0 / HZ)
	var v := w.get_ball_velocity(id)
	assert_true(v.is_finite())
	assert_almost_eq(v.y, -30.0, 0.01)


func test_balls_never_cross_walls_in_a_long_random_run() -> void:
	var t := TuningPresets.maze()
	t.max_speed = 3000.0
	var w := BallWorld.new(t)
	var rng := RandomNumberGenerator.new()
	rng.seed = 7
	# A box split by a thin diagonal wall and a horizontal one: balls start on known sides.
	var walls := [
		[Vector2(0, 0), Vector2(400, 0)],
		[Vector2(400, 0), Vector2(400, 400)],
		[Vector2(400, 400), Vector2(0, 400)],
		[Vector2(0, 400), Vector2(0, 0)],
		[Vector2(0, 200), Vector2(400, 200)],
	]
	for wl: Array in walls:
		w.shapes.add_wall(wl[0], wl[1], 1.0)
	var top: Array[int] = []
	for _i: int in 60:
		var p := Vector2(rng.randf_range(20, 380), rng.randf_range(20, 180))
		var v := Vector2(rng.randf_range(-3000, 3000), rng.randf_range(-3000, 3000))
		top.append(w.spawn_ball(p, v, 4.0))
	var crossed := 0
	for s: int in 600:
		var tilt := Vector2(sin(s * 0.05) * 15.0, cos(s * 0.037) * 15.0)
		MazeTilt.apply(w, tilt)
		if s % 100 == 0:
			for id: int in top:
				var kick := Vector2(rng.randf_range(-3000, 3000), rng.randf_range(-3000, 3000))
				w.set_ball_velocity(id, kick)
		w.step(1.0 / 60.0)
		for id: int in top:
			var p := w.get_ball_position(id)
			if p.y > 200.0 or p.x < 0.0 or p.x > 400.0 or p.y < 0.0:
				crossed += 1
	assert_eq(crossed, 0, "no ball left its half of the box")
