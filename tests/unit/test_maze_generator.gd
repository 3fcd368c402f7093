extends GutTest
## The maze generator: valid, solvable boards (holes never cut a start off), the same seed
## gives the same board, difficulty changes the maze, and bad settings are refused by name.

const MakeOriginalMazes := preload("res://tools/make_original_mazes.gd")


func _make(values: Dictionary) -> Dictionary:
	var settings := MazeGenSettings.new()
	settings.read(values)
	return MazeGenerator.generate(settings)


func test_a_generated_maze_is_a_valid_board_every_start_can_finish() -> void:
	for s in range(1, 21):
		var cols := 4 + s % 9
		var rows := 4 + (s * 7) % 11
		var made := _make(
			{"cols": cols, "rows": rows, "holes": floori(cols * rows / 6.0), "seed": s}
		)
		assert_false(made.has("error"), "seed %d: %s" % [s, made.get("error", "")])
		var level: BoardLevel = made["level"]
		assert_eq(level.size, Vector2(cols, rows) * 35.0)
		assert_eq(level.ball_starts.size(), 4)
		for issue in BoardValidator.validate(level):
			assert_false(issue.is_error(), "seed %d: %s" % [s, issue.message])
			assert_ne(issue.kind, "holes_block_goal", "seed %d: %s" % [s, issue.message])
		var with_holes := MazeFlood.new(level, true)
		for start in level.ball_starts:
			assert_true(with_holes.reaches_goal(start), "seed %d: start %s is cut off" % [s, start])


func test_holes_are_placed_as_asked_and_keep_off_starts_and_goal() -> void:
	var made := _make({"cols": 14, "rows": 12, "holes": 12, "seed": 5, "difficulty": 0.8})
	var level: BoardLevel = made["level"]
	assert_eq(int(made["holes_placed"]), 12)
	assert_eq(level.holes.size(), 12)
	for hole in level.holes:
		assert_gt(hole.distance_to(level.goal_center), level.goal_radius + level.hole_radius)
		for start in level.ball_starts:
			assert_gt(hole.distance_to(start), 35.0 * 1.5, "no hole beside a start")


func test_the_same_seed_gives_the_same_board_and_another_seed_another() -> void:
	var values := {"cols": 12, "rows": 10, "holes": 8, "seed": 42, "difficulty": 0.4}
	var a := BoardTextWriter.write(_make(values)["level"])
	var b := BoardTextWriter.write(_make(values)["level"])
	assert_eq(a, b)
	values["seed"] = 43
	assert_ne(a, BoardTextWriter.write(_make(values)["level"]))


func test_harder_mazes_have_more_walls_and_holes_in_corridors() -> void:
	var easy: BoardLevel = _make({"cols": 16, "rows": 14, "holes": 0, "difficulty": 0.0})["level"]
	var hard: BoardLevel = _make({"cols": 16, "rows": 14, "holes": 0, "difficulty": 1.0})["level"]
	assert_gt(_wall_length(hard), _wall_length(easy) * 1.2, "fewer loops knocked out")


func test_bad_settings_are_refused_by_name() -> void:
	assert_string_contains(str(_make({"cols": 2})["error"]), "columns and rows")
	assert_string_contains(str(_make({"rows": 99})["error"]), "columns and rows")
	assert_string_contains(str(_make({"holes": -1})["error"]), "Black holes")
	assert_string_contains(str(_make({"holes": 1000})["error"]), "Black holes")
	assert_string_contains(str(_make({"difficulty": NAN})["error"]), "Difficulty")
	assert_string_contains(str(_make({"difficulty": 1.5})["error"]), "Difficulty")
	assert_string_contains(str(MazeGenerator.generate(null)["error"]), "settings")


func test_smallest_maze_still_works() -> void:
	var made := _make({"cols": 4, "rows": 4, "holes": 4, "seed": 9})
	assert_false(made.has("error"), str(made.get("error", "")))
	var level: BoardLevel = made["level"]
	assert_eq(level.goal_center, Vector2(70, 70))


func _wall_length(level: BoardLevel) -> float:
	var total := 0.0
	for i in range(0, level.walls.size(), 2):
		total += level.walls[i].distance_to(level.walls[i + 1])
	return total


func test_no_wall_crosses_the_goal_ring_and_one_that_does_is_named() -> void:
	for s in range(1, 16):
		var made := _make({"cols": 4 + s % 11, "rows": 4 + (s * 5) % 9, "holes": 2, "seed": s})
		assert_false(made.has("error"), "seed %d: %s" % [s, made.get("error", "")])
		var level: BoardLevel = made["level"]
		assert_eq(MazeGenerator.wall_in_goal_ring(level), -1, "seed %d: the ring is clear" % s)
	# The same board with a wall laid through the goal: the check finds it.
	var level: BoardLevel = _make({"cols": 8, "rows": 8, "seed": 3})["level"]
	var walls := level.walls
	walls.append(level.goal_center + Vector2(-40.0, 20.0))
	walls.append(level.goal_center + Vector2(40.0, 20.0))
	level.walls = walls
	assert_eq(MazeGenerator.wall_in_goal_ring(level), walls.size() / 2 - 1, "the new wall")


func test_every_shipped_maze_board_but_the_tutorials_keeps_its_goal_ring_clear() -> void:
	# Every board in levels/maze, the two built with the editor's actions too (Catacombs
	# once had three walls through its ring); Classic keeps the tutorial's own layout, and
	# the two first boards put their small goal at a corridor's dead end on purpose (a ball
	# resting there is in: test_maze_first_board wins them by holding the arrows in turn).
	var checked: Array[String] = []
	for loaded in BoardLoader.list_boards(BoardLevel.Kind.MAZE):
		var id := loaded.path.get_file().get_basename()
		if id in ["classic", "first_roll", "two_together"]:
			continue
		checked.append(id)
		var crossing := MazeGenerator.wall_in_goal_ring(loaded.level)
		assert_eq(crossing, -1, "%s: wall %d crosses the goal ring" % [id, crossing])
	assert_true(checked.has("catacombs") and checked.has("courtyards"), str(checked))
	assert_eq(checked.size(), 11, "every shipped maze but those three: %s" % [checked])


func test_the_board_builder_refuses_a_wall_across_the_goal_ring() -> void:
	var level := MakeOriginalMazes.make_courtyards()
	assert_eq(MakeOriginalMazes.refuse_wall_in_goal_ring(level), level, "a clear ring passes")
	var walls := level.walls
	walls.append(level.goal_center + Vector2(-40.0, 0.0))
	walls.append(level.goal_center + Vector2(40.0, 0.0))
	level.walls = walls
	assert_null(MakeOriginalMazes.refuse_wall_in_goal_ring(level))
	assert_push_error("crosses the goal ring")
