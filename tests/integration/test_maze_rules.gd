extends GutTest
## The maze rules headless: the seed's tilt physics, walls and caps, win and loss, modes.

const CLASSIC := "res://levels/maze/classic.board"
## An open spot in the classic board's central plaza.
const PLAZA := Vector2(157.5, 122.5)


func _rules(hard := false) -> MazeRules:
	var rules := MazeRules.new(BoardLoader.load_board(CLASSIC).level, hard)
	rules.start()
	return rules


func _first(rules: MazeRules) -> int:
	return rules.world.get_ids()[0]


# Keeps every ball but the first out of the way in a corner cell.
func _only_first_moves(rules: MazeRules) -> void:
	var ids := rules.world.get_ids()
	for i in range(1, ids.size()):
		rules.world.remove_ball(ids[i])


func test_tilt_gives_the_seeds_acceleration_and_friction() -> void:
	var rules := _rules()
	rules.set_tilt(Vector2(12.0, -6.0))
	var g := 2.0 / (0.016 * 0.016)
	assert_almost_eq(rules.world.gravity.x, g * sin(deg_to_rad(12.0)), 0.01)
	assert_almost_eq(rules.world.gravity.y, g * sin(deg_to_rad(-6.0)), 0.01)
	assert_almost_eq(rules.world.rolling_friction.x, g * 0.01 * cos(deg_to_rad(12.0)), 0.001)
	assert_almost_eq(rules.world.rolling_friction.y, g * 0.01 * cos(deg_to_rad(6.0)), 0.001)


func test_tilt_is_clamped_to_twelve_degrees_per_axis() -> void:
	var rules := _rules()
	rules.set_tilt(Vector2(40.0, -99.0))
	assert_eq(rules.tilt, Vector2(12.0, -12.0))
	rules.set_tilt(Vector2(NAN, 3.0))
	assert_eq(rules.tilt, Vector2(0.0, 3.0), "a broken reading becomes flat, not NaN physics")


func test_one_step_on_a_slope_gains_g_sin_minus_friction() -> void:
	var rules := _rules()
	_only_first_moves(rules)
	var id := _first(rules)
	rules.world.set_ball_position(id, PLAZA)
	rules.set_tilt(Vector2(6.0, 0.0))
	rules.step()
	var g := 2.0 / (0.016 * 0.016)
	var dt := rules.step_seconds()
	var expected := (g * sin(deg_to_rad(6.0)) - g * 0.01 * cos(deg_to_rad(6.0))) * dt
	assert_almost_eq(rules.world.get_ball_velocity(id).x, expected, 0.01)
	assert_eq(rules.world.get_ball_velocity(id).y, 0.0)


func test_speed_is_capped_at_the_seeds_one_and_a_half_px_per_frame() -> void:
	var rules := _rules()
	_only_first_moves(rules)
	var id := _first(rules)
	rules.world.set_ball_position(id, Vector2(122.5, 192.5))
	rules.set_tilt(Vector2(12.0, 0.0))
	for i in 60:
		rules.step()
		assert_lte(rules.world.get_ball_velocity(id).length(), 1.5 / 0.016 + 0.001)


func test_flat_friction_slows_a_ball_but_never_reverses_it() -> void:
	var rules := _rules()
	_only_first_moves(rules)
	var id := _first(rules)
	rules.world.set_ball_position(id, PLAZA)
	rules.world.set_ball_velocity(id, Vector2(20.0, -12.0))
	rules.set_tilt(Vector2.ZERO)
	var previous := rules.world.get_ball_velocity(id)
	for i in 60:
		rules.step()
		var v := rules.world.get_ball_velocity(id)
		assert_true(v.x >= 0.0 and v.x <= previous.x, "x only slows (step %d: %s)" % [i, v])
		assert_true(v.y <= 0.0 and v.y >= previous.y, "y only slows (step %d: %s)" % [i, v])
		previous = v
	assert_eq(rules.world.get_ball_velocity(id), Vector2.ZERO, "friction brought it to rest")


func test_hitting_a_wall_body_keeps_a_third_of_the_normal_speed() -> void:
	var rules := _rules()
	_only_first_moves(rules)
	var id := _first(rules)
	# Cell (4, 4) has the wall x = 210 to its right; fly at it flat, at the speed cap.
	# the seed's wall response alone: this wall stands at the goal's edge, whose dish
	# (GoalDip) would pull the ball back
	rules.world.before_step = Callable()
	# and with no rolling friction: the level board's felt (MazeTilt.felt_drag, applied each
	# step) would slow it on the way
	rules.world.tuning = rules.world.tuning.duplicate()
	rules.world.tuning.rolling_friction = 0.0
	rules.world.set_ball_position(id, Vector2(190.0, 157.5))
	rules.world.set_ball_velocity(id, Vector2(93.75, 0.0))
	var bounced := Vector2.ZERO
	var before := Vector2.ZERO
	for i in 40:
		before = rules.world.get_ball_velocity(id)
		rules.step()
		var v := rules.world.get_ball_velocity(id)
		if v.x < 0.0:
			bounced = v
			break
	assert_gt(before.x, 80.0, "it hit the wall fast")
	assert_almost_eq(bounced.x, -before.x / 3.0, 1.0, "rebound at a third of the speed")
	assert_lte(rules.world.get_ball_position(id).x, 200.0 + 0.01, "never inside the wall")


func test_a_ball_driven_past_a_wall_end_rolls_round_the_cap() -> void:
	var level := _one_wall_board()
	var rules := MazeRules.new(level)
	rules.start()
	var id := _first(rules)
	# Pressed onto the top of the wall and pushed left: past x = 100 it must wrap the cap.
	rules.set_tilt(Vector2(-12.0, 12.0))
	var cap := Vector2(100.0, 100.0)
	var wrapped := false
	for i in 240:
		rules.step()
		var p := rules.world.get_ball_position(id)
		assert_gte(p.distance_to(cap), 10.0 - 0.05, "never inside the cap (step %d)" % i)
		if p.x > 100.0:
			assert_lte(p.y, 90.0 + 0.05, "rides on top of the wall, never through it")
		if p.y > 100.0 and p.x < 100.0:
			wrapped = true
			break
	assert_true(wrapped, "the ball went round the cap and down the far side")


func _one_wall_board() -> BoardLevel:
	var level := BoardLevel.new()
	level.kind = BoardLevel.Kind.MAZE
	level.board_id = "one_wall"
	level.size = Vector2(300.0, 300.0)
	level.ball_radius = 5.0
	level.wall_width = 10.0
	level.path_width = 25.0
	level.grid_cols = 1
	level.grid_rows = 1
	level.walls = PackedVector2Array([Vector2(100.0, 100.0), Vector2(200.0, 100.0)])
	level.ball_starts = PackedVector2Array([Vector2(150.0, 90.0)])
	level.goal_center = Vector2(250.0, 250.0)
	level.goal_radius = 20.0
	level.tuning = TuningPresets.maze()
	return level


func test_winning_needs_every_ball_in_the_goal() -> void:
	var rules := _rules()
	watch_signals(rules)
	var ids := rules.world.get_ids()
	var centre := rules.level.goal_center
	for i in 3:
		rules.world.set_ball_position(ids[i], centre + Vector2(-12.0 + 10.0 * i, 0.0))
	rules.world.set_ball_position(ids[3], Vector2(17.5, 17.5))
	rules.step()
	assert_eq(rules.balls_in_goal, 3)
	assert_eq(rules.state, MazeRules.State.PLAYING, "three of four is not a win")
	assert_signal_not_emitted(rules, "won")
	rules.world.set_ball_position(ids[3], centre + Vector2(0.0, 12.0))
	rules.step()
	assert_eq(rules.state, MazeRules.State.WON)
	assert_signal_emitted(rules, "won")
	var elapsed := rules.elapsed
	rules.step()
	assert_eq(rules.elapsed, elapsed, "the clock stops at the win")


func test_hard_mode_a_ball_in_a_hole_ends_the_game() -> void:
	var rules := _rules(true)
	watch_signals(rules)
	var id := _first(rules)
	var hole := rules.level.holes[1]
	rules.world.set_ball_position(id, hole + Vector2(-12.0, 0.0))
	rules.world.set_ball_velocity(id, Vector2(60.0, 0.0))
	for i in 60:
		rules.step()
	assert_eq(rules.state, MazeRules.State.LOST)
	assert_eq(rules.lost_hole, 1, "the hole that took the ball is known (drawn red)")
	assert_signal_emitted_with_parameters(rules, "lost", [1])
	assert_eq(rules.balls_lost(), 1)
	rules.reset()
	assert_eq(rules.state, MazeRules.State.READY)
	assert_eq(rules.lost_hole, -1)
	assert_eq(rules.world.ball_count(), 4, "a reset brings every ball back")


func test_easy_mode_has_no_holes() -> void:
	var rules := _rules(false)
	var id := _first(rules)
	var hole := rules.level.holes[1]
	rules.world.set_ball_position(id, hole + Vector2(-12.0, 0.0))
	rules.world.set_ball_velocity(id, Vector2(60.0, 0.0))
	for i in 60:
		rules.step()
	assert_eq(rules.state, MazeRules.State.PLAYING)
	assert_eq(rules.world.ball_count(), 4)


func test_mode_switches_reset_the_board() -> void:
	var rules := _rules()
	watch_signals(rules)
	rules.set_tilt(Vector2(12.0, 12.0))
	for i in 30:
		rules.step()
	rules.set_hard_mode(true)
	assert_true(rules.hard_mode)
	assert_eq(rules.state, MazeRules.State.READY)
	assert_eq(rules.tilt, Vector2.ZERO)
	assert_eq(rules.elapsed, 0.0)
	assert_eq(rules.ball_positions(), rules.level.ball_starts)
	assert_signal_emitted_with_parameters(rules, "mode_changed", [true])
	rules.set_hard_mode(false)
	assert_false(rules.hard_mode)
	assert_signal_emit_count(rules, "game_reset", 2)


func test_nothing_moves_before_the_start() -> void:
	var rules := MazeRules.new(BoardLoader.load_board(CLASSIC).level)
	rules.set_tilt(Vector2(12.0, 12.0))
	assert_eq(rules.advance(1.0), 0)
	assert_eq(rules.ball_positions(), rules.level.ball_starts)
	rules.start()
	assert_gt(rules.advance(0.1), 0)
	assert_ne(rules.ball_positions(), rules.level.ball_starts)


func test_a_pachinko_board_is_refused_clearly() -> void:
	var board := BoardLevel.new()
	board.kind = BoardLevel.Kind.PACHINKO
	var rules := MazeRules.new(board)
	assert_push_error("needs a maze board")
	assert_false(rules.is_ready())
	rules.start()
	assert_eq(rules.advance(1.0), 0)
