extends GutTest
## Floor arrows, the kind that came as one row: the editor's own tool for it (from the row)
## places one, select drags it, mirror mode paints a twin pointing the other way, the
## property panel turns it, erase removes it, each one undo step; the board file keeps it;
## the 2D painter and the maze's 3D floor draw it.

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const BoardInput := preload("res://addons/board_editor/board_input.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const ItemNames := preload("res://addons/board_editor/core/item_names.gd")
const ItemProperties := preload("res://addons/board_editor/core/item_properties.gd")
const Layers := preload("res://addons/board_editor/core/layers.gd")
const Shortcuts := preload("res://addons/board_editor/ui/shortcuts.gd")
const FIXTURE := "res://tests/fixtures/boards/floor_arrows.board"
const SPOT := Vector2(52.5, 52.5)

var session: BoardEditSession
var input: BoardInput
var kind := ItemKinds.of_list("floor_arrows")


func _open(path := "res://levels/maze/first_roll.board") -> BoardLevel:
	var level: BoardLevel = BoardTextReader.read(FileAccess.get_file_as_string(path))["level"]
	session = BoardEditSession.new(level)
	input = BoardInput.new(session)
	session.snap_enabled = false
	return level


func _press(at: Vector2, down: bool) -> void:
	var event := InputEventMouseButton.new()
	event.button_index = MOUSE_BUTTON_LEFT
	event.pressed = down
	event.position = at
	input.handle(event, Transform2D.IDENTITY)


func _click(at: Vector2) -> void:
	_press(at, true)
	_press(at, false)


# The tool the floor arrow row brings.
func _arrow_tool() -> int:
	var rows := BoardEditSession.row_tools()
	for tool: int in rows:
		if rows[tool] == kind:
			return tool
	return -1


func test_the_row_brings_a_maze_tool_with_its_key() -> void:
	var tool := _arrow_tool()
	assert_gt(tool, -1, "the floor arrow row has a tool")
	_open()
	assert_has(session.available_tools(), tool, "a maze board offers it")
	assert_eq(Shortcuts.name_of(tool), "Floor arrow")
	var key := InputEventKey.new()
	key.keycode = KEY_Y
	assert_eq(Shortcuts.tool_for(key), tool)
	assert_has(Layers.for_kind(BoardLevel.Kind.MAZE), "Floor arrows")


func test_the_tool_places_one_in_one_undo_step_and_the_file_keeps_it() -> void:
	var level := _open()
	session.set_tool(_arrow_tool())
	_click(SPOT)
	assert_eq(level.floor_arrows.size(), 1)
	assert_eq(level.floor_arrows[0].position, SPOT)
	var item := BoardItems.make(kind.pick, 0)
	assert_eq(session.selection, [item] as Array[Vector2i])
	assert_eq(ItemNames.name_of(level, item), "Floor arrow 1")
	assert_eq(session.history.names()[-1], "Add floor arrow")
	var text := BoardTextWriter.write(level)
	assert_string_contains(text, '{"floor_arrow": {"id": 1, "x": 52.5, "y": 52.5, "angle": 0}}')
	var back: BoardLevel = BoardTextReader.read(text)["level"]
	assert_eq(back.floor_arrows[0].position, SPOT, "read back where it was placed")
	session.history.undo()
	assert_eq(level.floor_arrows.size(), 0)


func test_mirror_mode_paints_a_twin_pointing_the_other_way() -> void:
	var level := _open()
	session.mirror_enabled = true
	session.set_tool(_arrow_tool())
	_click(SPOT)
	assert_eq(level.floor_arrows.size(), 2)
	assert_eq(level.floor_arrows[1].position, Vector2(level.size.x - SPOT.x, SPOT.y))
	assert_eq(absf(level.floor_arrows[1].angle), 180.0, "right becomes left")


func test_the_angle_field_turns_it_and_undo_turns_it_back() -> void:
	var level := _open(FIXTURE)
	var item := BoardItems.make(kind.pick, 1)
	assert_eq(ItemProperties.values_of(level, item).keys(), ["x", "y", "angle"])
	session.commit(ItemProperties.action_for(level, item, "angle", 90.0))
	assert_eq(level.floor_arrows[1].angle, 90.0)
	assert_eq(session.history.names()[-1], "Set floor arrow angle")
	session.history.undo()
	assert_eq(level.floor_arrows[1].angle, 180.0)


func test_select_drags_it_and_erase_removes_it() -> void:
	var level := _open(FIXTURE)
	var at := level.floor_arrows[0].position
	session.set_tool(BoardEditSession.Tool.SELECT)
	_press(at, true)
	for step in [0.5, 1.0]:
		var motion := InputEventMouseMotion.new()
		motion.position = at + Vector2(0, 10) * step
		motion.button_mask = MOUSE_BUTTON_MASK_LEFT
		input.handle(motion, Transform2D.IDENTITY)
	_press(at + Vector2(0, 10), false)
	assert_eq(level.floor_arrows[0].position, at + Vector2(0, 10))
	session.set_tool(BoardEditSession.Tool.ERASE)
	_click(at + Vector2(0, 10))
	assert_eq(level.floor_arrows.size(), 2)
	session.history.undo()
	assert_eq(level.floor_arrows.size(), 3)


func test_the_maze_floor_paints_each_arrow_flat_on_the_floor() -> void:
	var level: BoardLevel = BoardTextReader.read(FileAccess.get_file_as_string(FIXTURE))["level"]
	var mesh := MazeFloorArrows.arrows_mesh(level)
	assert_not_null(mesh)
	var corners: PackedVector3Array = mesh.surface_get_arrays(0)[Mesh.ARRAY_VERTEX]
	assert_eq(corners.size(), 3 * 5 * 3, "three arrows of five triangles")
	for corner in corners:
		assert_almost_eq(corner.z, MazeFloorArrows.LIFT_PX * 0.01, 0.0001, "flat on the floor")
	level.floor_arrows = [] as Array[FloorArrowSpec]
	assert_null(MazeFloorArrows.arrows_mesh(level), "no arrows, no mesh")


func test_the_board_painter_draws_them_on_their_layer() -> void:
	var level: BoardLevel = BoardTextReader.read(FileAccess.get_file_as_string(FIXTURE))["level"]
	var canvas: Control = add_child_autofree(Control.new())
	var drawn := [0]
	var paint := func() -> void:
		drawn[0] += 1
		BoardPainter.draw_board(canvas, level)
	canvas.draw.connect(paint)
	canvas.queue_redraw()
	await get_tree().process_frame
	# GUT fails the test on any engine or script error raised while drawing.
	assert_eq(drawn[0], 1)
	var hidden: Array[String] = ["Floor arrows"]
	assert_eq(Layers.painter_mask(hidden), BoardPainter.Layer.FLOOR_ARROWS)
	assert_eq(level.floor_arrows[0].polygon().size(), 7, "an arrow is one 7-corner shape")
