extends GutTest
## The end dots of a selected wall are handles: dragging one moves that end of that wall
## only (never the whole wall, never the other wall sharing the corner), in one undo step.

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const TestEditorTools := preload("res://tests/unit/test_editor_tools.gd")
const TestEditorActions := preload("res://tests/unit/test_editor_actions.gd")

var _helper: TestEditorTools


func before_each() -> void:
	_helper = TestEditorTools.new()


func after_each() -> void:
	_helper.free()


# Two walls meeting at (105, 105): an L.
func _corner_board() -> BoardLevel:
	var level := TestEditorActions.maze()
	level.walls = PackedVector2Array(
		[Vector2(35, 105), Vector2(105, 105), Vector2(105, 105), Vector2(105, 35)]
	)
	ItemIds.fill(level)
	return level


func test_dragging_a_selected_walls_end_moves_only_that_end() -> void:
	_helper.start(_corner_board())
	var session := _helper.session
	session.set_snap(false)
	session.select([BoardItems.make(BoardItems.Kind.WALL, 0)] as Array[Vector2i])
	_helper.press(Vector2(105, 105), true)
	_helper.move(Vector2(120, 110))
	_helper.move(Vector2(140, 115))
	_helper.press(Vector2(140, 115), false)
	var walls := session.level.walls
	assert_eq(walls[0], Vector2(35, 105), "the far end stays")
	assert_eq(walls[1], Vector2(140, 115), "the dragged end follows the mouse")
	assert_eq(walls[2], Vector2(105, 105), "the other wall at the corner stays")
	assert_eq(walls[3], Vector2(105, 35))
	assert_eq(session.selection, [BoardItems.make(BoardItems.Kind.WALL, 0)], "still selected")
	assert_eq(session.history.names()[-1], "Move wall end", "one step named for what it did")
	session.history.undo()
	assert_eq(session.level.walls[1], Vector2(105, 105), "one undo puts the end back")


func test_with_the_second_wall_selected_its_end_moves_instead() -> void:
	_helper.start(_corner_board())
	var session := _helper.session
	session.select([BoardItems.make(BoardItems.Kind.WALL, 1)] as Array[Vector2i])
	_helper.press(Vector2(106, 104), true)
	_helper.move(Vector2(130, 104))
	_helper.move(Vector2(141, 104))
	_helper.press(Vector2(141, 104), false)
	var walls := session.level.walls
	assert_eq(walls[1], Vector2(105, 105), "wall 1's end at the corner stays")
	assert_eq(walls[2], Vector2(140, 105), "wall 2's end snaps to the maze grid corner")
	assert_eq(walls[3], Vector2(105, 35))


func test_a_press_on_the_walls_round_cap_beside_the_dot_grabs_the_end() -> void:
	_helper.start(_corner_board())
	var session := _helper.session
	session.set_snap(false)
	session.select([BoardItems.make(BoardItems.Kind.WALL, 0)] as Array[Vector2i])
	# 10 px from the end dot at (105, 105): on the 10 px wall's cap, past the 8 px pick.
	_helper.press(Vector2(113, 111), true)
	_helper.move(Vector2(125, 115))
	_helper.move(Vector2(133, 121))
	_helper.press(Vector2(133, 121), false)
	var walls := session.level.walls
	assert_eq(walls[0], Vector2(35, 105), "the far end stays: not the whole wall")
	assert_eq(walls[1], Vector2(125, 115), "the grabbed end moves by the drag, no jump")


func test_dragging_the_middle_of_a_wall_still_moves_the_whole_wall() -> void:
	_helper.start(_corner_board())
	var session := _helper.session
	session.set_snap(false)
	session.select([BoardItems.make(BoardItems.Kind.WALL, 0)] as Array[Vector2i])
	_helper.press(Vector2(70, 105), true)
	_helper.move(Vector2(70, 120))
	_helper.move(Vector2(70, 125))
	_helper.press(Vector2(70, 125), false)
	assert_eq(session.level.walls[0], Vector2(35, 125))
	assert_eq(session.level.walls[1], Vector2(105, 125))


func test_erase_on_a_ball_start_over_a_wall_erases_the_start() -> void:
	var level := _corner_board()
	# A start sitting over the first wall, 3 px below its line.
	level.ball_starts = PackedVector2Array([Vector2(70, 108)])
	ItemIds.fill(level)
	_helper.start(level)
	var session := _helper.session
	session.set_tool(BoardEditSession.Tool.ERASE)
	_helper.click(Vector2(70, 106))  # inside the start, and deeper inside the wall
	assert_eq(session.level.ball_starts.size(), 0, "the start is gone")
	assert_eq(BoardItems.wall_count(session.level.walls), 2, "the wall under it stays")


func test_with_both_walls_selected_a_drag_at_the_corner_moves_both() -> void:
	_helper.start(_corner_board())
	var session := _helper.session
	session.set_snap(false)
	var both: Array[Vector2i] = [
		BoardItems.make(BoardItems.Kind.WALL, 0), BoardItems.make(BoardItems.Kind.WALL, 1)
	]
	session.select(both)
	_helper.press(Vector2(105, 105), true)
	_helper.move(Vector2(110, 105))
	_helper.move(Vector2(115, 105))
	_helper.press(Vector2(115, 105), false)
	assert_eq(session.level.walls[0], Vector2(45, 105), "the whole selection moved")
	assert_eq(session.level.walls[3], Vector2(115, 35))


func test_ghosts_turn_red_where_a_click_would_add_an_error() -> void:
	var level := _load_board("res://levels/pachinko/classic.board")
	_helper.start(level)
	var session := _helper.session
	session.set_tool(BoardEditSession.Tool.POCKET)
	var pockets: Variant = _helper.input.active_tool()
	assert_false(pockets.would_add_error(Vector2(350, 200)), "a clear spot stays green")
	assert_true(pockets.would_add_error(Vector2(5, 350)), "outside the ring is red")
	var maze := _load_board("res://levels/maze/classic.board")
	_helper.start(maze)
	_helper.session.set_tool(BoardEditSession.Tool.HOLE)
	var holes: Variant = _helper.input.active_tool()
	assert_true(holes.would_add_error(maze.ball_starts[0]), "a hole on a ball start is red")
	assert_eq(maze.holes.size(), 8, "asking never changes the board")


func test_the_goal_ghost_turns_red_over_walls_starts_and_holes() -> void:
	var maze := _load_board("res://levels/maze/classic.board")
	_helper.start(maze)
	_helper.session.set_tool(BoardEditSession.Tool.GOAL)
	var goal: Variant = _helper.input.active_tool()
	assert_false(goal.would_add_error(maze.goal_center), "where it is now: clear")
	assert_true(goal.would_add_error(maze.ball_starts[0]), "on a ball start")
	var wall_middle := (maze.walls[20] + maze.walls[21]) * 0.5
	assert_true(goal.would_add_error(wall_middle), "on a wall")
	assert_true(goal.would_add_error(maze.holes[0]), "on a black hole")


func _load_board(path: String) -> BoardLevel:
	var result := BoardLoader.load_board(path)
	assert_not_null(result.level, result.error)
	return result.level
