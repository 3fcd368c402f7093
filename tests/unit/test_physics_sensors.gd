extends GutTest
## Sensors fire exactly once: holes (centre within the radius, even for a fast ball),
## goals (reached / left), zones; events arrive in step order.

const DT := 1.0 / 120.0


func _world() -> BallWorld:
	var t := TuningPresets.maze()
	t.max_speed = 5000.0
	t.rolling_friction = 0.0
	return BallWorld.new(t)


func test_hole_swallows_a_ball_once() -> void:
	var w := _world()
	var hole := w.shapes.add_hole(Vector2(100, 0), 9.0)
	var got: Array = []
	w.ball_fell_in_hole.connect(func(b: int, h: int) -> void: got.append([b, h]))
	var id := w.spawn_ball(Vector2(0, 0), Vector2(90, 0), 5.0)
	for _i: int in 240:
		w.step(DT)
	assert_eq(got, [[id, hole]])
	assert_false(w.has_ball(id))


func test_ball_passing_beside_a_hole_does_not_fall() -> void:
	var w := _world()
	w.shapes.add_hole(Vector2(100, 0), 9.0)
	var got := [0]
	w.ball_fell_in_hole.connect(func(_b: int, _h: int) -> void: got[0] += 1)
	w.spawn_ball(Vector2(0, 9.5), Vector2(90, 0), 5.0)
	for _i: int in 240:
		w.step(DT)
	assert_eq(got[0], 0, "the centre never came within the radius")


func test_fast_ball_cannot_skip_a_hole() -> void:
	var w := _world()
	w.shapes.add_hole(Vector2(100, 0), 9.0)
	var got := [0]
	w.ball_fell_in_hole.connect(func(_b: int, _h: int) -> void: got[0] += 1)
	w.spawn_ball(Vector2(0, 0), Vector2(4000, 0), 5.0)
	for _i: int in 10:
		w.step(1.0 / 60.0)
	assert_eq(got[0], 1)


func test_goal_reports_entering_and_leaving_once_each() -> void:
	var w := _world()
	var goal := w.shapes.add_goal(Vector2(100, 0), 30.0)
	var log: Array = []
	w.ball_reached_goal.connect(func(b: int, g: int) -> void: log.append(["in", b, g]))
	w.ball_left_goal.connect(func(b: int, g: int) -> void: log.append(["out", b, g]))
	var id := w.spawn_ball(Vector2(0, 0), Vector2(90, 0), 5.0)
	for _i: int in 360:
		w.step(DT)
	assert_eq(log, [["in", id, goal], ["out", id, goal]])
	assert_true(w.has_ball(id), "a goal keeps the ball")


func test_zone_entry_fires_once_per_entry() -> void:
	var w := _world()
	var zone := w.shapes.add_zone(Vector2(0, 0), 20.0)
	var got: Array = []
	w.ball_entered_zone.connect(func(b: int, z: int) -> void: got.append([b, z]))
	var id := w.spawn_ball(Vector2(-50, 0), Vector2(90, 0), 5.0)
	for _i: int in 120:
		w.step(DT)
	assert_eq(got, [[id, zone]])
	w.set_ball_velocity(id, Vector2(-90, 0))
	for _i: int in 120:
		w.step(DT)
	assert_eq(got, [[id, zone], [id, zone]], "coming back in counts again")


func test_events_come_in_step_order() -> void:
	var w := _world()
	w.shapes.add_wall(Vector2(50, -50), Vector2(50, 50), 5.0)
	w.shapes.add_hole(Vector2(-100, 0), 9.0)
	var log: Array[String] = []
	w.wall_hit.connect(func(_b: int, _i: int, _s: float) -> void: log.append("wall"))
	w.ball_fell_in_hole.connect(func(_b: int, _h: int) -> void: log.append("hole"))
	w.spawn_ball(Vector2(0, 0), Vector2(3000, 0), 5.0)
	for _i: int in 60:
		w.step(DT)
	assert_eq(log, ["wall", "hole"])


func test_signal_handler_may_spawn_and_remove_balls() -> void:
	var w := _world()
	w.shapes.add_hole(Vector2(100, 0), 9.0)
	var spawned: Array[int] = []
	w.ball_fell_in_hole.connect(
		func(_b: int, _h: int) -> void:
			spawned.append(w.spawn_ball(Vector2.ZERO, Vector2.ZERO, 5.0))
	)
	var other := w.spawn_ball(Vector2(0, 50), Vector2.ZERO, 5.0)
	w.ball_fell_in_hole.connect(func(_b: int, _h: int) -> void: w.remove_ball(other))
	w.spawn_ball(Vector2(0, 0), Vector2(90, 0), 5.0)
	for _i: int in 240:
		w.step(DT)
	assert_eq(spawned.size(), 1)
	assert_true(w.has_ball(spawned[0]))
	assert_false(w.has_ball(other))
	assert_eq(w.ball_count(), 1)
	# The handlers hold the world: drop them so the world is freed.
	for c: Dictionary in w.ball_fell_in_hole.get_connections():
		w.ball_fell_in_hole.disconnect(c["callable"])
