extends GutTest
## The goal's dish (GoalDip): a ball that rolls in stays in, even with the board tilted fully
## away, and settles near the middle; a ball drawn over the rim counts and is pulled in;
## clear of the rim nothing changes (play trials saw balls roll across the goal and out
## again, and a ball drawn over the rim left uncounted).


func _rules() -> MazeRules:
	var rules := MazeRules.new(BoardLoader.load_board("res://levels/maze/cloister.board").level)
	rules.start()
	return rules


# Moves every ball but the first far from the goal (they would count too) and puts the
# first at `at` with velocity `velocity`, rolling free: these cases are about the dish, and
# since maze rules 5 the felt of a level board stops a coasting ball within a few pixels
# (a 60 px/s ball in about 5 px), before it reaches the dish, so the world's copy of its
# tuning has no rolling friction (nor felt, which is a part of it).
func _place(rules: MazeRules, at: Vector2, velocity: Vector2) -> int:
	var free_rolling := rules.world.tuning.duplicate() as PhysicsTuning
	free_rolling.rolling_friction = 0.0
	rules.world.tuning = free_rolling
	var ids := rules.world.get_ids()
	for i in ids.size():
		if i > 0:
			rules.world.remove_ball(ids[i])
	rules.world.set_ball_position(ids[0], at)
	rules.world.set_ball_velocity(ids[0], velocity)
	return ids[0]


func test_a_ball_in_the_dish_stays_in_at_full_tilt_away() -> void:
	for tilt: Vector2 in [Vector2(TiltInput.MAX_TILT_DEG, 0.0), Vector2(8.5, 8.5)]:
		_check_held_at(tilt)


# The keys and sticks reach full tilt on one axis or 8.5 degrees on both.
func _check_held_at(tilt: Vector2) -> void:
	var rules := _rules()
	var goal := rules.level.goal_center
	var id := _place(rules, goal + Vector2(10.0, 0.0), Vector2.ZERO)
	rules.set_tilt(tilt)
	for i in 240:  # two seconds
		rules.step()
	var offset := rules.world.get_ball_position(id) - goal
	assert_lt(offset.length(), rules.level.goal_radius, "%s: in the dish at %s" % [tilt, offset])
	assert_lt(offset.length(), GoalDip.REST_OFFSET_PX * 2.0, "%s: resting near the middle" % tilt)


func test_a_ball_rolling_across_the_rim_is_caught() -> void:
	var rules := _rules()
	var goal := rules.level.goal_center
	var radius := rules.level.goal_radius
	var id := _place(rules, goal + Vector2(-radius + 2.0, 8.0), Vector2(90.0, 0.0))
	for i in 240:
		rules.step()
	var offset := rules.world.get_ball_position(id) - goal
	assert_lt(offset.length(), radius, "caught, not rolled across")


func test_the_pull_is_toward_the_middle_and_only_inside_the_rim() -> void:
	var rules := _rules()
	var dip := GoalDip.new(rules.world, rules.level)
	var radius := rules.level.goal_radius
	var full_tilt := (
		MazeTilt.gravity(Vector2(TiltInput.MAX_TILT_DEG, 0.0), rules.world.tuning.tilt_gravity).x
	)
	var near_rim := dip.pull_at(Vector2(radius - 1.0, 0.0))
	assert_lt(near_rim.x, 0.0, "toward the middle")
	assert_gt(-near_rim.x, full_tilt, "harder than the steepest tilt")
	var reach := radius + rules.level.ball_radius
	assert_lt(dip.pull_at(Vector2(reach - 1.0, 0.0)).x, 0.0, "a disc over the rim is pulled")
	assert_eq(dip.pull_at(Vector2(reach + 1.0, 0.0)), Vector2.ZERO, "nothing once clear of it")
	assert_eq(dip.pull_at(Vector2.ZERO), Vector2.ZERO, "nothing at the middle")


func test_a_world_without_the_dip_steps_as_before() -> void:
	var rules := _rules()
	rules.world.before_step = Callable()
	var goal := rules.level.goal_center
	var id := _place(rules, goal + Vector2(-rules.level.goal_radius + 2.0, 8.0), Vector2(90.0, 0.0))
	for i in 240:
		rules.step()
	var offset := rules.world.get_ball_position(id) - goal
	assert_gt(offset.length(), rules.level.goal_radius, "without it the ball rolls on out")


# A designer's wall may cross the goal's circle: a ball on its far side is in the next
# corridor, not in the dish, and is not pulled into the wall.
func test_a_ball_behind_a_wall_inside_the_rim_is_not_pulled() -> void:
	var level := BoardLoader.load_board("res://levels/maze/cloister.board").level
	level = level.duplicate(true) as BoardLevel
	var across := level.goal_center + Vector2(12.0, 0.0)
	var walls := level.walls
	walls.append(across + Vector2(0.0, -30.0))
	walls.append(across + Vector2(0.0, 30.0))
	level.walls = walls
	var rules := MazeRules.new(level)
	var dip := GoalDip.new(rules.world, level)
	assert_eq(dip.pull_at(Vector2(18.0, 0.0)), Vector2.ZERO, "behind the wall")
	assert_lt(dip.pull_at(Vector2(8.0, 0.0)).x, 0.0, "this side of it")


# The dish steers the balls inside its rim only: a ball held there must not wake the others
# every step (it did: BallWorld.set_ball_velocity wakes every ball), so a ball resting
# against a wall far from the goal still falls asleep while another sits in the dish.
func test_a_ball_held_in_the_dish_lets_the_others_sleep() -> void:
	var rules := _rules()
	var goal := rules.level.goal_center
	var ids := rules.world.get_ids()
	rules.world.set_ball_position(ids[0], goal + Vector2(6.0, 0.0))
	rules.world.set_ball_velocity(ids[0], Vector2.ZERO)
	rules.set_tilt(Vector2(TiltInput.MAX_TILT_DEG, 0.0))
	for i in 600:  # five seconds: the others roll to the right-hand walls and rest there
		rules.step()
	var offset := rules.world.get_ball_position(ids[0]) - goal
	assert_lt(offset.length(), rules.level.goal_radius, "the first ball is still held")
	var sleeping := 0
	for i in range(1, ids.size()):
		var at := rules.world.get_ball_position(ids[i]) - goal
		if at.length() >= rules.level.goal_radius and rules.world.is_ball_asleep(ids[i]):
			sleeping += 1
	assert_gt(sleeping, 0, "a ball resting outside the dish sleeps though one is held in it")


# Who the dish touches: only balls whose centre is inside its rim, and only themselves.
func test_the_dish_wakes_only_the_balls_it_holds() -> void:
	var rules := _rules()
	var ids := rules.world.get_ids()
	var dip := GoalDip.new(rules.world, rules.level)
	for i in 240:  # two level seconds: every ball rests at its start and sleeps
		rules.step()
	for id in ids:
		assert_true(rules.world.is_ball_asleep(id), "ball %d asleep at its start" % id)
	rules.world.set_ball_position(ids[0], rules.level.goal_center + Vector2(8.0, 0.0))
	for i in 240:
		rules.step()
	dip.apply(1.0 / 120.0)
	for i in range(1, ids.size()):
		assert_true(rules.world.is_ball_asleep(ids[i]), "ball %d left asleep" % ids[i])
	assert_false(rules.world.is_ball_asleep(ids[0]), "the held ball is the one it moved")


# Cloister with every wall near its goal taken away, so a ball can roll across the dish.
func _open_goal_level() -> BoardLevel:
	var level := BoardLoader.load_board("res://levels/maze/cloister.board").level
	level = level.duplicate(true) as BoardLevel
	var kept := PackedVector2Array()
	for i in range(0, level.walls.size() - 1, 2):
		var a := level.walls[i]
		var b := level.walls[i + 1]
		var gap := Geometry2D.get_closest_point_to_segment(level.goal_center, a, b)
		if gap.distance_to(level.goal_center) > 60.0:
			kept.append(a)
			kept.append(b)
	level.walls = kept
	return level


# Before maze rules 4 the first two ended on the rim or beside it (24 and 29 px from the
# middle), neither counted nor pulled: the dish only reached a ball whose centre crossed it.
func test_a_modest_ball_crossing_the_goal_ends_in_it() -> void:
	var level := _open_goal_level()
	var reach := level.goal_radius + level.ball_radius
	for case: Array in [[18.0, 60.0], [24.0, 80.0], [10.0, 90.0]]:
		var rules := MazeRules.new(level)
		rules.start()
		var from := level.goal_center + Vector2(-40.0, case[0])
		var id := _place(rules, from, Vector2(case[1], 0.0))
		for i in 240:  # two seconds
			rules.step()
		var offset := rules.world.get_ball_position(id) - level.goal_center
		assert_lt(offset.length(), level.goal_radius, "%s px off the middle at %s px/s: in" % case)
		assert_eq(rules.balls_in_goal, 1, "%s: counted" % [case])
		assert_lt(offset.length(), reach)


# A ball the player sees over the rim counts at once (before rules 4 one resting 27 px from
# the middle, its disc 2 px over the 24 px rim, did not).
func test_a_ball_drawn_over_the_rim_counts() -> void:
	var level := _open_goal_level()
	var reach := level.goal_radius + level.ball_radius
	for side: Vector2 in [Vector2.LEFT, Vector2.UP, Vector2(1.0, 1.0).normalized()]:
		var rules := MazeRules.new(level)
		rules.start()
		_place(rules, level.goal_center + side * (reach - 2.0), Vector2.ZERO)
		rules.step()
		assert_eq(rules.balls_in_goal, 1, "%s: drawn over the rim, counted" % side)
		var clear := MazeRules.new(level)
		clear.start()
		_place(clear, level.goal_center + side * (reach + 1.0), Vector2.ZERO)
		clear.step()
		assert_eq(clear.balls_in_goal, 0, "%s: its disc clear of the rim, not counted" % side)
