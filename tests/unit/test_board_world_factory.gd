extends GutTest
## BoardWorldFactory builds the right world, and the launch rail works in it: a strong shot
## goes round the rail into the field, a weak one rolls back into the return zone (zone 0).

const CLASSIC := "res://levels/pachinko/classic.board"
const MAZE := "res://levels/maze/classic.board"
const DT := 1.0 / 120.0


func test_pachinko_world_has_the_boards_shapes() -> void:
	var level: BoardLevel = load(CLASSIC)
	var world := BoardWorldFactory.build(level)
	assert_eq(world.shapes.pin_count(), level.pins.size())
	# Guide capsules, then the stopper and the deflector.
	assert_eq(world.shapes.wall_count(), LaunchRail.guide_points(level).size() - 1 + 2)
	assert_eq(world.tuning, level.tuning)


func test_strong_shot_goes_round_the_rail_into_the_field() -> void:
	var level: BoardLevel = load(CLASSIC)
	var world := BoardWorldFactory.build(level)
	var zones: Array[int] = []
	world.ball_entered_zone.connect(func(_id: int, zone: int) -> void: zones.append(zone))
	var speed := LaunchRail.speed_to_clear(level, world.gravity.y) * 1.5
	var id := world.spawn_ball(
		LaunchRail.launch_position(level), LaunchRail.launch_direction(level) * speed, 5.0
	)
	var topmost := INF
	var entered_field := false
	for step in 600:
		world.step(DT)
		if not world.has_ball(id):
			break
		var p := world.get_ball_position(id)
		topmost = minf(topmost, p.y)
		if p.distance_to(level.ring_center) < LaunchRail.guide_radius(level) - 20.0:
			entered_field = true
			break
	assert_true(entered_field, "the ball left the rail into the field")
	assert_lt(topmost, level.ring_center.y - level.ring_radius * 0.8, "it went over the top")
	assert_eq(zones, [] as Array[int], "it never rolled back")


func test_weak_shot_rolls_back_into_zone_0() -> void:
	var level: BoardLevel = load(CLASSIC)
	var world := BoardWorldFactory.build(level)
	var zones: Array[int] = []
	world.ball_entered_zone.connect(func(_id: int, zone: int) -> void: zones.append(zone))
	var id := world.spawn_ball(
		LaunchRail.launch_position(level), LaunchRail.launch_direction(level) * 300.0, 5.0
	)
	for step in 600:
		world.step(DT)
		if not zones.is_empty():
			break
	assert_eq(zones, [0] as Array[int])
	assert_true(world.has_ball(id), "the rules, not the world, return it to the cup")
	assert_gt(world.get_ball_position(id).y, level.ring_center.y, "it is at the bottom")


func test_launch_helpers_point_up_the_rail() -> void:
	var level: BoardLevel = load(CLASSIC)
	var start := LaunchRail.launch_position(level)
	assert_gt(start.x, level.ring_center.x, "the rail is on the right")
	assert_gt(start.y, level.ring_center.y, "the launcher is near the bottom")
	assert_lt(LaunchRail.launch_direction(level).y, 0.0, "fired upwards")
	assert_almost_eq(LaunchRail.launch_direction(level).length(), 1.0, 1e-5)
	var zone := LaunchRail.return_zone_center(level)
	assert_gt(zone.y, start.y, "the return zone is below the launch position")
	assert_gt(start.distance_to(zone), LaunchRail.return_zone_radius(level) + level.ball_radius)


func test_maze_world_walls_goal_and_holes_in_hard_mode_only() -> void:
	var level: BoardLevel = load(MAZE)
	var easy := BoardWorldFactory.build(level)
	assert_eq(easy.shapes.wall_count(), level.walls.size() / 2 + 4, "the level's walls and 4 edges")
	var falls: Array[int] = []
	easy.ball_fell_in_hole.connect(func(_id: int, hole: int) -> void: falls.append(hole))
	easy.spawn_ball(level.holes[0], Vector2.ZERO, 5.0)
	easy.step(DT)
	assert_eq(falls, [] as Array[int], "no holes in easy mode")
	var hard := BoardWorldFactory.build(level, true)
	hard.ball_fell_in_hole.connect(func(_id: int, hole: int) -> void: falls.append(hole))
	hard.spawn_ball(level.holes[3] + Vector2(1, 0), Vector2.ZERO, 5.0)
	hard.step(DT)
	assert_eq(falls, [3] as Array[int])


func test_maze_goal_is_goal_0() -> void:
	var level: BoardLevel = load(MAZE)
	var world := BoardWorldFactory.build(level)
	var goals: Array[int] = []
	world.ball_reached_goal.connect(func(_id: int, goal: int) -> void: goals.append(goal))
	world.spawn_ball(level.goal_center + Vector2(0, 40), Vector2(0, -80), 5.0)
	for step in 120:
		world.step(DT)
	assert_eq(goals, [0] as Array[int])


func test_missing_tuning_uses_the_defaults_and_null_level_is_refused() -> void:
	var level: BoardLevel = (load(CLASSIC) as BoardLevel).duplicate_level()
	level.tuning = null
	var world := BoardWorldFactory.build(level)
	assert_almost_eq(world.gravity.y, TuningPresets.pachinko().gravity.y, 1e-3)
	assert_null(BoardWorldFactory.build(null))
	assert_push_error("no level")
