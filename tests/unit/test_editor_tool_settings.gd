extends GutTest
## Tool settings survive switching to another board (a scene tab switch makes a new
## session): the tool, snap, grid, mirror, pattern, curve, pocket sizes and clipboard.

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const ToolSettings := preload("res://addons/board_editor/core/tool_settings.gd")
const NewBoard := preload("res://addons/board_editor/core/new_board.gd")


func test_settings_carry_over_to_the_next_board() -> void:
	var first := BoardEditSession.new(NewBoard.make(BoardLevel.Kind.PACHINKO))
	first.set_tool(BoardEditSession.Tool.PATTERN)
	first.set_snap(false)
	first.set_mirror(true)
	first.grid_step = 5.0
	first.pattern["count"] = 11
	first.curve["count"] = 7
	first.pocket_payout = 4
	var kept := ToolSettings.capture(first)
	first.pattern["count"] = 99  # a later change on the old board does not leak into the copy
	var second := BoardEditSession.new(NewBoard.make(BoardLevel.Kind.PACHINKO))
	ToolSettings.apply(second, kept)
	assert_eq(second.tool, BoardEditSession.Tool.PATTERN, "the pattern tool is still picked")
	assert_false(second.snap_enabled)
	assert_true(second.mirror_enabled)
	assert_eq(second.grid_step, 5.0)
	assert_eq(second.pattern["count"], 11)
	assert_eq(second.curve["count"], 7)
	assert_eq(second.pocket_payout, 4)


func test_a_tool_the_next_board_lacks_falls_back_to_select() -> void:
	var maze := BoardEditSession.new(NewBoard.make(BoardLevel.Kind.MAZE))
	maze.set_tool(BoardEditSession.Tool.WALL)
	var pachinko := BoardEditSession.new(NewBoard.make(BoardLevel.Kind.PACHINKO))
	ToolSettings.apply(pachinko, ToolSettings.capture(maze))
	assert_eq(pachinko.tool, BoardEditSession.Tool.SELECT, "no wall tool on a pachinko board")
