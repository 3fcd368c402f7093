extends GutTest
## The maze autoplay: it plays the classic board to the goal, the same seed plays the same
## game, and its planner reads the board's grid right.

const CLASSIC := "res://levels/maze/classic.board"

const RIGHT := 0
const DOWN := 2
const UP := 3
const DOWN_RIGHT := 4


func _level() -> BoardLevel:
	return BoardLoader.load_board(CLASSIC).level


func test_autoplay_brings_balls_into_the_goal_on_classic_easy() -> void:
	var result := MazeAutoplay.run(_level(), 120.0, 1)
	assert_gte(int(result["max_balls_in_goal"]), 2, "at least two balls reached the goal")
	assert_true(result["won"], "seed 1 wins outright: %s" % [result])
	assert_gt(float(result["time_to_win"]), 0.0)
	assert_lte(float(result["time_to_win"]), 120.0)
	assert_eq(int(result["balls_in_goal"]), 4)
	assert_eq(int(result["balls_lost_in_holes"]), 0)


func test_the_same_seed_gives_the_same_result() -> void:
	var a := MazeAutoplay.run(_level(), 15.0, 3)
	var b := MazeAutoplay.run(_level(), 15.0, 3)
	assert_eq(JSON.stringify(a), JSON.stringify(b))
	var steps_per_second := _level().tuning.fixed_hz
	assert_eq(int(a["frames_simulated"]), roundi(15.0 * steps_per_second), "15 s of fixed steps")
	var c := MazeAutoplay.run(_level(), 15.0, 4)
	assert_ne(a["state_hash"], c["state_hash"], "another seed plays differently")


func test_hard_mode_autoplay_keeps_balls_out_of_holes() -> void:
	var result := MazeAutoplay.run(_level(), 10.0, 2, true)
	assert_true(result["hard_mode"])
	assert_true(result.has("balls_lost_in_holes"))
	assert_eq(int(result["balls_lost_in_holes"]), 0, "the hole guard keeps every ball out")
	var all_steps := roundi(10.0 * _level().tuning.fixed_hz)
	assert_eq(int(result["frames_simulated"]), all_steps, "no ball fell, so the game ran on")


func test_hole_guard_checks_a_new_wish_at_once() -> void:
	# A ball resting just beside the hole at (297.5, 52.5): tilting left is safe and passes;
	# the next step a new plan wants right, into the hole, before the next timed check.
	var guard := MazeHoleGuard.new(_level(), 1.0 / _level().tuning.fixed_hz)
	var at := PackedVector2Array([Vector2(290.9, 59.75)])
	var still := PackedVector2Array([Vector2.ZERO])
	assert_eq(guard.filter(Vector2(-9.7, 0.0), at, still), Vector2(-9.7, 0.0), "safe: passes")
	var tilt := guard.filter(Vector2(9.7, 0.0), at, still)
	assert_ne(tilt, Vector2(9.7, 0.0), "a tilt into the hole is checked, not waved through")


func test_hard_mode_classic_seed_3_keeps_every_ball() -> void:
	# Seed 3 lost a ball when a new plan's first tilt passed the guard unchecked. Seeds 1-20
	# are measured by tools/maze_pilot_table.gd --board=classic --hard-seeds=20 (all won,
	# no ball lost); one full game is enough for the suite.
	var result := MazeAutoplay.run(_level(), 120.0, 3, true)
	assert_eq(int(result["balls_lost_in_holes"]), 0, "%s" % [result])
	assert_true(result["won"])


func test_bad_input_is_refused_clearly() -> void:
	var pachinko := BoardLevel.new()
	pachinko.kind = BoardLevel.Kind.PACHINKO
	var result := MazeAutoplay.run(pachinko, 10.0, 1)
	assert_push_error("a maze board is needed")
	assert_false(result.get("ok", true))
	result = MazeAutoplay.run(_level(), -1.0, 1)
	assert_false(result.get("ok", true))
	assert_string_contains(str(result["error"]), "seconds")


func test_the_grid_reads_the_seed_walls() -> void:
	var grid := MazeGrid.new(_level())
	assert_true(grid.is_grid)
	assert_eq(grid.cell, Vector2(35.0, 35.0))
	assert_true(grid.is_open(0, 0, 1, 0), "cell (0,0) opens to the right")
	assert_false(grid.is_open(2, 0, 1, 0), "wall after the third column, top row")
	assert_false(grid.is_open(0, 0, 0, -1), "the border")
	assert_eq(grid.slide(0, RIGHT), 2, "top-left ball rolls right to (2, 0)")
	assert_eq(grid.slide(0, DOWN), 5 * 10, "and down to (0, 5)")
	assert_eq(grid.slide(grid.cell_at(Vector2(157.5, 157.5)), RIGHT), 4 * 10 + 5)


func test_steps_move_one_cell_and_hard_mode_knows_the_holes() -> void:
	var grid := MazeGrid.new(_level())
	var step_down := MazeGrid.FIRST_STEP + DOWN
	assert_eq(grid.slide(0, step_down), 10, "a step goes one cell")
	assert_eq(grid.slide(2, MazeGrid.FIRST_STEP + RIGHT), 2, "a wall holds a stepping ball")
	var hard := MazeGrid.new(_level(), true)
	assert_eq(hard.slide(0, RIGHT), -1, "rolling right from (0, 0) crosses the hole at (2, 0)")
	assert_eq(hard.slide(1, MazeGrid.FIRST_STEP + RIGHT), -1, "stepping into a hole")
	assert_eq(hard.slide(0, step_down), 10, "a safe step stays safe")


func test_the_planner_gathers_every_ball_from_the_starts() -> void:
	var level := _level()
	var grid := MazeGrid.new(level)
	var planner := MazeSlidePlanner.new(grid, MazeNav.new(level))
	var cells := planner.cells_of(level.ball_starts)
	assert_true(planner.plan(cells, PackedInt32Array([0, 1, 2, 3, 4, 5, 6, 7])))
	assert_between(planner.moves.size(), 5, 20)
	var state := cells
	for move in planner.moves:
		state = planner.predict(state, move)
	assert_eq(state, planner.target, "the moves lead to the planned state")
	for c in state:
		assert_eq(c, state[0], "every ball in one cell")


func test_the_distance_field_leads_to_the_goal() -> void:
	var level := _level()
	var nav := MazeNav.new(level)
	assert_lt(nav.distance_at(level.goal_center), 3.0)
	for start in level.ball_starts:
		var d := nav.distance_at(start)
		assert_between(d, 100.0, 2000.0, "every start reaches the goal")
		var ahead := nav.carrot(start, 10.0)
		assert_lt(nav.distance_at(ahead), d, "the carrot is nearer the goal")
