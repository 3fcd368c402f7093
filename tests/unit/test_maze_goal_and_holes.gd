extends GutTest
## The tilt maze's goal and holes as the player meets them: the clock, the goal count the
## side panel shows, the win only when every ball is in, and a hole ending the game (and
## only while it is being played). Balls are put in the goal by hand and the world's hole
## events are sent here directly, so each case is exact.

const CLASSIC := "res://levels/maze/classic.board"


func _rules(hard := false) -> MazeRules:
	var rules := MazeRules.new(BoardLoader.load_board(CLASSIC).level, hard)
	rules.start()
	return rules


# Puts the first `count` balls (or ball `only`) at rest in the goal, apart from each other.
func _enter_goal(rules: MazeRules, count: int, only := -1) -> void:
	var ids := rules.world.get_ids()
	var spots: Array[Vector2] = [Vector2(-7, -7), Vector2(7, -7), Vector2(-7, 7), Vector2(7, 7)]
	for i in ids.size():
		if i < count or ids[i] == only:
			rules.world.set_ball_position(ids[i], rules.level.goal_center + spots[i % 4])
			rules.world.set_ball_velocity(ids[i], Vector2.ZERO)


# Puts ball `id` back at rest on its start, far from the goal.
func _leave_goal(rules: MazeRules, id: int) -> void:
	rules.world.set_ball_position(id, rules.level.ball_starts[rules.world.get_ids().find(id)])
	rules.world.set_ball_velocity(id, Vector2.ZERO)


func test_the_clock_runs_one_step_at_a_time_while_playing() -> void:
	var rules := MazeRules.new(BoardLoader.load_board(CLASSIC).level)
	assert_eq(rules.run_steps(5), 0, "nothing runs before the start")
	assert_eq(rules.elapsed, 0.0)
	rules.start()
	rules.run_steps(5)
	assert_almost_eq(rules.elapsed, 5.0 * rules.step_seconds(), 1e-9)
	rules.run_steps(3)
	assert_almost_eq(rules.elapsed, 8.0 * rules.step_seconds(), 1e-9)


func test_the_goal_count_follows_the_balls_in_and_out() -> void:
	var rules := _rules()
	watch_signals(rules)
	_enter_goal(rules, 2)
	assert_eq(rules.count_in_goal(), 2)
	rules.run_steps(1)
	assert_eq(rules.balls_in_goal, 2)
	assert_signal_emitted_with_parameters(rules, "goal_count_changed", [2])
	rules.run_steps(1)
	assert_signal_emit_count(rules, "goal_count_changed", 1, "told once, not every step")
	_leave_goal(rules, rules.world.get_ids()[0])
	assert_eq(rules.count_in_goal(), 1, "a ball rolling out counts off")
	rules.run_steps(1)
	assert_eq(rules.balls_in_goal, 1)
	assert_signal_emitted_with_parameters(rules, "goal_count_changed", [1])


func test_every_ball_in_the_goal_wins_with_the_time() -> void:
	var rules := _rules()
	watch_signals(rules)
	rules.run_steps(10)
	_enter_goal(rules, rules.ball_total() - 1)
	rules.run_steps(1)
	assert_eq(rules.state, MazeRules.State.PLAYING, "all but one is not a win")
	assert_signal_not_emitted(rules, "won")
	var last: int = rules.world.get_ids()[rules.ball_total() - 1]
	_enter_goal(rules, 0, last)
	rules.run_steps(1)
	assert_eq(rules.state, MazeRules.State.WON)
	assert_signal_emitted_with_parameters(rules, "won", [rules.elapsed])
	assert_almost_eq(rules.elapsed, 12.0 * rules.step_seconds(), 1e-9, "twelve steps played")


func test_a_board_without_balls_is_never_won() -> void:
	var level := BoardLoader.load_board(CLASSIC).level.duplicate(true) as BoardLevel
	level.ball_starts = PackedVector2Array()
	var rules := MazeRules.new(level)
	rules.start()
	rules.run_steps(3)
	assert_eq(rules.state, MazeRules.State.PLAYING, "no balls in the goal of no balls")


func test_a_ball_missing_from_the_board_keeps_the_win_away() -> void:
	var rules := _rules()
	_enter_goal(rules, rules.ball_total())
	rules.world.remove_ball(rules.world.get_ids()[0])
	rules.run_steps(1)
	assert_eq(rules.state, MazeRules.State.PLAYING, "four counted in, but only three on the board")


func test_the_first_hole_ends_the_game_and_is_named() -> void:
	var rules := _rules(true)
	watch_signals(rules)
	rules.run_steps(4)
	rules.world.ball_fell_in_hole.emit(rules.world.get_ids()[0], 0)
	assert_eq(rules.state, MazeRules.State.LOST)
	assert_eq(rules.lost_hole, 0, "hole 0 is a hole too")
	assert_eq(rules.balls_lost(), 1)
	assert_signal_emitted_with_parameters(rules, "lost", [0])
	var elapsed := rules.elapsed
	rules.run_steps(5)
	assert_eq(rules.elapsed, elapsed, "the clock stopped")
	rules.world.ball_fell_in_hole.emit(rules.world.get_ids()[1], 3)
	assert_eq(rules.lost_hole, 0, "a second ball after the end changes nothing")
	assert_signal_emit_count(rules, "lost", 1)


func test_a_hole_after_the_win_or_before_the_start_changes_nothing() -> void:
	var rules := _rules(true)
	_enter_goal(rules, rules.ball_total())
	rules.run_steps(1)
	assert_eq(rules.state, MazeRules.State.WON)
	rules.world.ball_fell_in_hole.emit(rules.world.get_ids()[0], 2)
	assert_eq(rules.state, MazeRules.State.WON)
	assert_eq(rules.balls_lost(), 0)
	var waiting := MazeRules.new(BoardLoader.load_board(CLASSIC).level, true)
	waiting.world.ball_fell_in_hole.emit(waiting.world.get_ids()[0], 1)
	assert_eq(waiting.state, MazeRules.State.READY)
	assert_eq(waiting.lost_hole, -1)
	assert_eq(waiting.balls_lost(), 0, "no ball lost yet")


func test_a_board_that_could_not_be_built_shows_no_ball_in_the_goal() -> void:
	var board := BoardLevel.new()
	board.kind = BoardLevel.Kind.PACHINKO
	var rules := MazeRules.new(board)
	assert_push_error("needs a maze board")
	assert_eq(rules.count_in_goal(), 0)
	assert_eq(rules.balls_lost(), 0)


func test_a_one_ball_board_is_won_by_its_one_ball() -> void:
	var level := BoardLoader.load_board(CLASSIC).level.duplicate(true) as BoardLevel
	level.ball_starts = PackedVector2Array([level.ball_starts[0]])
	var rules := MazeRules.new(level)
	rules.start()
	_enter_goal(rules, 1)
	rules.run_steps(1)
	assert_eq(rules.state, MazeRules.State.WON)


func test_the_step_a_ball_falls_in_does_not_count_on_the_clock() -> void:
	var rules := _rules(true)
	var id: int = rules.world.get_ids()[0]
	var hole := rules.level.holes[1]
	rules.world.set_ball_position(id, hole + Vector2(-12.0, 0.0))
	rules.world.set_ball_velocity(id, Vector2(60.0, 0.0))
	var played := 0
	for i in 120:
		rules.step()
		if rules.state != MazeRules.State.PLAYING:
			break
		played += 1
	assert_eq(rules.state, MazeRules.State.LOST, "the ball fell in")
	assert_almost_eq(rules.elapsed, played * rules.step_seconds(), 1e-9, "the clock stopped first")
