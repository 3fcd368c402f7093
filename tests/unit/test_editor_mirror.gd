extends GutTest
## Mirror mode: one edit lands on both halves of the board.

const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const Mirror := preload("res://addons/board_editor/core/mirror.gd")
const ActionHistory := preload("res://addons/board_editor/core/action_history.gd")
const PocketAction := preload("res://addons/board_editor/actions/pocket_action.gd")
const WallAction := preload("res://addons/board_editor/actions/wall_action.gd")
const MoveItemsAction := preload("res://addons/board_editor/actions/move_items_action.gd")
const TestEditorActions := preload("res://tests/unit/test_editor_actions.gd")


func test_axis_is_the_ring_centre_or_the_board_middle() -> void:
	assert_eq(Mirror.axis_of(TestEditorActions.pachinko()), 300.0)
	assert_eq(Mirror.axis_of(TestEditorActions.maze()), 175.0)


func test_mirrored_wall_and_pocket() -> void:
	var maze := TestEditorActions.maze()
	var history := ActionHistory.new()
	history.commit(WallAction.new(maze, Vector2(35, 70), Vector2(105, 70), 175.0))
	assert_eq(
		maze.walls,
		PackedVector2Array([Vector2(35, 70), Vector2(105, 70), Vector2(315, 70), Vector2(245, 70)])
	)
	history.undo()
	assert_eq(maze.walls.size(), 0, "one undo removes both halves")
	var board := TestEditorActions.pachinko()
	history.commit(PocketAction.new(board, Vector2(200, 400), 30, 24, 5, 300.0))
	assert_eq(board.pockets.size(), 2)
	assert_eq(board.pockets[1].position, Vector2(400, 400))
	history.commit(PocketAction.new(board, Vector2(300, 300), 30, 24, 5, 300.0))
	assert_eq(board.pockets.size(), 3, "a pocket on the axis is not doubled")


func test_partners_and_erasing_both_halves() -> void:
	var maze := TestEditorActions.maze()
	maze.holes = PackedVector2Array([Vector2(50, 50), Vector2(300, 50), Vector2(175, 90)])
	var left := BoardItems.make(BoardItems.Kind.HOLE, 0)
	assert_eq(Mirror.partner(maze, left, 175.0), BoardItems.make(BoardItems.Kind.HOLE, 1))
	assert_eq(
		Mirror.partner(maze, BoardItems.make(BoardItems.Kind.HOLE, 2), 175.0),
		BoardItems.make(BoardItems.Kind.HOLE, 2),
		"on the axis"
	)
	var both := Mirror.with_partners(maze, [left] as Array[Vector2i], 175.0)
	assert_eq(both.size(), 2)


func test_mirrored_move_reflects_the_offset() -> void:
	var maze := TestEditorActions.maze()
	maze.holes = PackedVector2Array([Vector2(50, 50), Vector2(300, 50), Vector2(175, 90)])
	var picked: Array[Vector2i] = [
		BoardItems.make(BoardItems.Kind.HOLE, 0), BoardItems.make(BoardItems.Kind.HOLE, 2)
	]
	var split := Mirror.split_for_move(maze, picked, 175.0, 50.0)
	var move := MoveItemsAction.new(
		maze, split["direct"], Vector2(10, 5), split["mirrored"], split["on_axis"]
	)
	ActionHistory.new().commit(move)
	assert_eq(maze.holes[0], Vector2(60, 55))
	assert_eq(maze.holes[1], Vector2(290, 55), "the partner moves the mirrored way")
	assert_eq(maze.holes[2], Vector2(175, 95), "the axis hole only moves vertically")


func test_dragging_the_right_half_of_a_selected_pair() -> void:
	var maze := TestEditorActions.maze()
	maze.holes = PackedVector2Array([Vector2(50, 50), Vector2(300, 50)])
	var picked: Array[Vector2i] = [
		BoardItems.make(BoardItems.Kind.HOLE, 0), BoardItems.make(BoardItems.Kind.HOLE, 1)
	]
	var split := Mirror.split_for_move(maze, picked, 175.0, 300.0)
	ActionHistory.new().commit(
		MoveItemsAction.new(maze, split["direct"], Vector2(10, 0), split["mirrored"])
	)
	assert_eq(maze.holes[1], Vector2(310, 50), "the grabbed hole follows the mouse")
	assert_eq(maze.holes[0], Vector2(40, 50))
