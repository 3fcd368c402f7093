extends GutTest
## The maze board check refuses a gap narrower than a ball between walls, a wall end and the
## frame (a ball wedges in it: the pilot lost whole games to one), and reachability is
## checked even when other errors exist, or a warning says why it was not.


func _classic() -> BoardLevel:
	var result := BoardLoader.load_board("res://levels/maze/classic.board")
	assert_not_null(result.level, result.error)
	return result.level


# The classic maze with only a top border wall (its face at y = 5) and the frame.
func _open_board() -> BoardLevel:
	var level := _classic()
	level.walls = PackedVector2Array([Vector2(0, 0), Vector2(350, 0)])
	level.wall_ids = PackedInt32Array()
	ItemIds.fill(level)
	return level


func _add_wall(level: BoardLevel, a: Vector2, b: Vector2) -> int:
	var walls := level.walls
	walls.append(a)
	walls.append(b)
	level.walls = walls
	ItemIds.fill(level)
	@warning_ignore("integer_division")
	return ItemIds.of(level, "walls", walls.size() / 2 - 1)


func _messages(level: BoardLevel, code: String) -> PackedStringArray:
	var found := PackedStringArray()
	for issue in BoardValidator.validate(level):
		if issue.kind == code:
			found.append(issue.message)
	return found


func test_a_wall_end_five_pixels_from_a_wall_is_refused_naming_the_gap() -> void:
	var level := _open_board()
	# The top border wall's face is at y = 5; this wall's end cap stops 5 px below it.
	var id := _add_wall(level, Vector2(100, 15), Vector2(100, 60))
	var gaps := _messages(level, "maze_narrow_gap")
	assert_eq(gaps.size(), 1, str(gaps))
	if gaps.size() == 1:
		assert_string_contains(gaps[0], "Walls 1 and %d leave a 5.0 px gap at (100, " % id)
		assert_string_contains(gaps[0], "a ball (10 px) cannot pass but wedges in it")
	var errors := BoardValidator.errors(level)
	assert_true(errors.any(func(i: BoardIssue) -> bool: return i.kind == "maze_narrow_gap"))
	var loaded := BoardLoader.validated("trap.board", level)
	assert_null(loaded.level, "a board with the trap is refused")
	assert_string_contains(loaded.error, "leave a 5.0 px gap")


func test_a_gap_to_the_board_edge_is_refused_too() -> void:
	var level := _open_board()
	# The frame itself holds the balls on the left: this wall's cap face is 6 px from x = 0.
	var id := _add_wall(level, Vector2(11, 100), Vector2(60, 100))
	var gaps := _messages(level, "maze_narrow_gap")
	assert_eq(
		gaps,
		PackedStringArray(
			[
				(
					(
						"Wall %d leaves a 6.0 px gap to the board's edge at (3, 100): "
						+ "a ball (10 px) cannot pass but wedges in it. Close the gap or widen it."
					)
					% id
				)
			]
		)
	)


func test_walls_that_meet_or_leave_room_for_a_ball_pass() -> void:
	var level := _open_board()
	_add_wall(level, Vector2(100, 10), Vector2(100, 60))  # touches the border wall
	assert_eq(
		_messages(level, "maze_narrow_gap"), PackedStringArray(), "walls that meet are no gap"
	)
	level = _open_board()
	_add_wall(level, Vector2(100, 21), Vector2(100, 60))  # 11 px: a ball passes
	assert_eq(_messages(level, "maze_narrow_gap").size(), 0, "a gap a ball fits through")


func test_shipped_mazes_have_no_narrow_gaps() -> void:
	for loaded in BoardLoader.list_boards(BoardLevel.Kind.MAZE):
		assert_not_null(loaded.level, loaded.error)
		if loaded.level != null:
			assert_eq(_messages(loaded.level, "maze_narrow_gap"), PackedStringArray(), loaded.path)


func test_a_boxed_in_start_is_reported_beside_other_errors() -> void:
	var level := _classic()
	var start := level.ball_starts[0]
	# Box the first start in, and add an unrelated error (a zero-length wall).
	var half := 15.0
	var corners := [
		start + Vector2(-half, -half),
		start + Vector2(half, -half),
		start + Vector2(half, half),
		start + Vector2(-half, half)
	]
	for k in 4:
		_add_wall(level, corners[k], corners[(k + 1) % 4])
	_add_wall(level, Vector2(200, 200), Vector2(200, 200))
	assert_eq(_messages(level, "wall_zero_length").size(), 1, "the other error is there")
	assert_eq(
		_messages(level, "start_cannot_reach_goal"),
		PackedStringArray(["Ball start 1 cannot roll to the goal: wall 50 closes it in."]),
		"and the boxed-in start is still reported (its box's other three walls back onto the maze's)"
	)


func test_a_skipped_reachability_check_says_why() -> void:
	var level := _classic()
	var walls := level.walls
	walls[3] = Vector2(NAN, 10)
	level.walls = walls
	assert_eq(
		_messages(level, "reachability_skipped"),
		PackedStringArray(
			[
				(
					"Whether every ball can roll to the goal was not checked: "
					+ "a wall has an end that is not a number."
				)
			]
		)
	)
