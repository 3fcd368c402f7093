extends GutTest
## BoardValidator's maze checks: walls, starts, goal, holes and whether balls can reach the
## goal (flood fill with walls grown by the ball radius).

const DIR := "res://tests/fixtures/boards/"


func test_maze_walls() -> void:
	var level := _maze()
	_add_wall(level, Vector2(50, 70), Vector2(50, 70))
	assert_has(_codes(level), "wall_zero_length")
	level = _maze()
	_add_wall(level, Vector2(50, 70), Vector2(500, 70))
	assert_has(_codes(level), "wall_outside")
	level = _maze()
	var walls := level.walls
	walls.append(Vector2(1, 1))
	level.walls = walls
	assert_eq(_codes(level), ["odd_wall_points", "reachability_skipped"], "and says so")


func test_maze_starts() -> void:
	var level := _maze()
	level.ball_starts = PackedVector2Array([Vector2(35, 35)])  # on the inner wall
	assert_has(_codes(level), "start_in_wall")
	level.ball_starts = PackedVector2Array([Vector2(-20, 35)])
	assert_has(_codes(level), "start_outside")
	level.ball_starts = PackedVector2Array([Vector2(87.5, 80)])
	assert_has(_codes(level), "start_in_hole")
	level.ball_starts = PackedVector2Array([Vector2(17.5, 17.5), Vector2(22, 17.5)])
	assert_eq(_codes(level), ["starts_overlap"])
	level.ball_starts = PackedVector2Array()
	assert_has(_codes(level), "no_starts")


func test_goal_hanging_off_the_board_is_a_warning() -> void:
	var level := _maze()
	level.goal_center = Vector2(level.size.x - 5.0, level.size.y * 0.5)
	assert_has(_codes(level), "goal_off_board")
	level = _maze()
	assert_does_not_have(_codes(level), "goal_off_board")


func test_start_that_cannot_reach_the_goal() -> void:
	var level := _maze()
	# Close the gap at the right end of the inner wall: the start's strip is sealed off.
	_add_wall(level, Vector2(70, 35), Vector2(105, 35))
	var issues := BoardValidator.validate(level)
	assert_eq(_codes(level), ["start_cannot_reach_goal"])
	assert_eq(issues[0].position, level.ball_starts[0], "marked at the start")


func test_gap_narrower_than_a_ball_blocks_the_way() -> void:
	var level := _maze()
	# Leave a 9 px gap (wall surfaces 9 px apart) where a 10 px ball cannot pass.
	_add_wall(level, Vector2(89, 35), Vector2(105, 35))
	assert_eq(_codes(level), ["maze_narrow_gap", "start_cannot_reach_goal"], "a trap, and closed")
	level = _maze()
	_add_wall(level, Vector2(95, 35), Vector2(105, 35))  # a 15 px gap: passable
	assert_eq(_codes(level), [])


func test_holes_that_cut_off_the_goal_warn() -> void:
	var level := _maze()
	level.holes = PackedVector2Array([Vector2(87.5, 35)])  # in the only gap down
	var issues := BoardValidator.validate(level)
	assert_eq(_codes(level), ["holes_block_goal"])
	assert_false(issues[0].is_error())


func test_maze_goal() -> void:
	var level := _maze()
	level.goal_radius = 3.0
	assert_has(_codes(level), "bad_goal")


func _maze() -> BoardLevel:
	return (load(DIR + "tiny_maze.tres") as BoardLevel).duplicate_level()


func _add_wall(level: BoardLevel, a: Vector2, b: Vector2) -> void:
	var walls := level.walls
	walls.append(a)
	walls.append(b)
	level.walls = walls


func _codes(level: BoardLevel) -> Array[String]:
	var codes: Array[String] = []
	for issue in BoardValidator.validate(level):
		codes.append(issue.kind)
	return codes
