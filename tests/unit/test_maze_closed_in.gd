extends GutTest
## A maze where a ball cannot reach the goal gets one problem per cause, naming the goal or
## the starts closed in and the walls that close them in (which the editor highlights).


# The classic maze's size, four starts in its corners and the goal in the middle, no walls.
func _open_maze() -> BoardLevel:
	var result := BoardLoader.load_board("res://levels/maze/classic.board")
	assert_not_null(result.level, result.error)
	var level := result.level
	level.walls = PackedVector2Array()
	level.wall_ids = PackedInt32Array()
	level.holes = PackedVector2Array()
	level.hole_ids = PackedInt32Array()
	level.ball_starts = PackedVector2Array(
		[Vector2(17.5, 17.5), Vector2(332.5, 17.5), Vector2(17.5, 297.5), Vector2(332.5, 297.5)]
	)
	level.start_ids = PackedInt32Array()
	level.goal_center = Vector2(175, 157.5)
	ItemIds.fill(level)
	return level


# Walls round the box `corners` (four points), appended to `level`.
func _box(level: BoardLevel, centre: Vector2, half: Vector2) -> void:
	var walls := level.walls
	var corners := [
		centre - half,
		centre + Vector2(half.x, -half.y),
		centre + half,
		centre + Vector2(-half.x, half.y)
	]
	for k in 4:
		walls.append(corners[k])
		walls.append(corners[(k + 1) % 4])
	level.walls = walls
	ItemIds.fill(level)


func _closed(level: BoardLevel) -> Array[BoardIssue]:
	var found: Array[BoardIssue] = []
	for issue in BoardValidator.validate(level):
		if issue.kind in ["goal_closed_in", "start_cannot_reach_goal"]:
			found.append(issue)
	return found


func test_a_boxed_in_goal_is_one_problem_naming_the_goal_and_its_walls() -> void:
	var level := _open_maze()
	level.walls = PackedVector2Array([Vector2(0, 0), Vector2(350, 0)])  # wall 1, far away
	ItemIds.fill(level)
	_box(level, level.goal_center, Vector2(70, 52.5))
	var closed := _closed(level)
	assert_eq(closed.size(), 1, "one cause, not one copy per start")
	if closed.is_empty():
		return
	assert_eq(closed[0].kind, "goal_closed_in")
	assert_eq(
		closed[0].message,
		"The goal is closed in by walls 2, 3, 4 and 5: none of the 4 ball starts can roll to it."
	)
	assert_eq(closed[0].position, level.goal_center, "marked at the goal")
	assert_eq(closed[0].segments, level.walls.slice(2), "the four walls are pointed at")


func test_a_boxed_in_start_names_its_own_walls_only() -> void:
	var level := _open_maze()
	_box(level, level.goal_center, Vector2(70, 52.5))
	var walls := level.walls
	walls.remove_at(0)  # open the goal's box: take its top wall away
	walls.remove_at(0)
	level.walls = walls
	level.wall_ids = PackedInt32Array()
	ItemIds.fill(level)
	assert_eq(_closed(level).size(), 0, "an open box closes nothing in")
	# Walls round start 1 in its corner: ids 8-11 (ids are never handed out twice). Walls 8
	# and 11 run along the board's edge: only 9 and 10 stand between the start and the goal.
	_box(level, Vector2(35, 35), Vector2(35, 35))
	var closed := _closed(level)
	assert_eq(closed.size(), 1)
	if closed.is_empty():
		return
	assert_eq(
		closed[0].message, "Ball start 1 cannot roll to the goal: walls 9 and 10 close it in."
	)
	assert_eq(closed[0].kind, "start_cannot_reach_goal")
	assert_true(closed[0].extent().has_point(level.goal_center), "framed with the goal")
	assert_eq(closed[0].segments.size(), 4, "the two walls are pointed at")


func test_starts_closed_in_together_share_one_problem() -> void:
	var level := _open_maze()
	# A wall across the board's bottom third: starts 3 and 4 below it, with the board's edge.
	level.walls = PackedVector2Array([Vector2(0, 245), Vector2(350, 245)])
	ItemIds.fill(level)
	var closed := _closed(level)
	assert_eq(closed.size(), 1)
	if closed.is_empty():
		return
	assert_eq(
		closed[0].message,
		"Ball starts 3 and 4 cannot roll to the goal: wall 1 and the board's edge close them in."
	)
