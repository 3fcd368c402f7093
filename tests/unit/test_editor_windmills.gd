extends GutTest
## Windmills in the board editor: the Windmill tool places one (two in mirror mode, the
## twin turning the other way), select drags it, the property panel's fields change its
## blades, speed or free spin, erase removes it; each gesture one undo step, ids kept, and
## the file written as the game reads it.

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const BoardInput := preload("res://addons/board_editor/board_input.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const ItemNames := preload("res://addons/board_editor/core/item_names.gd")
const ItemProperties := preload("res://addons/board_editor/core/item_properties.gd")
const Layers := preload("res://addons/board_editor/core/layers.gd")
const CLASSIC := "res://levels/pachinko/classic.board"
const SPOT := Vector2(300, 260)

var session: BoardEditSession
var input: BoardInput


func _open() -> BoardLevel:
	var level: BoardLevel = BoardTextReader.read(FileAccess.get_file_as_string(CLASSIC))["level"]
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


func _drag(from: Vector2, to: Vector2) -> void:
	_press(from, true)
	for step in [0.5, 1.0]:
		var event := InputEventMouseMotion.new()
		event.position = from.lerp(to, step)
		event.button_mask = MOUSE_BUTTON_MASK_LEFT
		input.handle(event, Transform2D.IDENTITY)
	_press(to, false)


func test_the_windmill_tool_places_one_in_one_undo_step() -> void:
	var level := _open()
	assert_true(session.available_tools().has(BoardEditSession.Tool.WINDMILL))
	session.set_tool(BoardEditSession.Tool.WINDMILL)
	_click(SPOT)
	assert_eq(level.windmills.size(), 1)
	var spec := level.windmills[0]
	assert_eq(spec.position, SPOT)
	assert_false(spec.free_spin)
	assert_eq(spec.speed, WindmillSpec.DEFAULT_SPEED)
	assert_eq(session.selection, [BoardItems.make(BoardItems.Kind.WINDMILL, 0)] as Array[Vector2i])
	assert_eq(ItemNames.name_of(level, session.selection[0]), "Windmill 1")
	assert_eq(Layers.of_item(session.selection[0]), "Windmills")
	assert_string_contains(
		BoardTextWriter.write(level),
		'{"windmill": {"id": 1, "x": 300, "y": 260, "blades": 4, "length": 22, "speed": 120}}'
	)
	session.history.undo()
	assert_eq(level.windmills.size(), 0)
	session.history.redo()
	assert_eq(level.windmills.size(), 1)


func test_mirror_mode_places_a_twin_that_turns_the_other_way() -> void:
	var level := _open()
	session.mirror_enabled = true
	session.set_tool(BoardEditSession.Tool.WINDMILL)
	_click(SPOT)
	assert_eq(level.windmills.size(), 2)
	assert_eq(level.windmills[1].position, Vector2(400, 260))
	assert_eq(level.windmills[1].speed, -level.windmills[0].speed)


func test_select_drags_a_windmill_and_undo_puts_it_back() -> void:
	var level := _open()
	session.set_tool(BoardEditSession.Tool.WINDMILL)
	_click(SPOT)
	session.set_tool(BoardEditSession.Tool.SELECT)
	_drag(SPOT + Vector2(3, 3), SPOT + Vector2(33, 23))
	assert_eq(level.windmills[0].position, SPOT + Vector2(30, 20))
	session.history.undo()
	assert_eq(level.windmills[0].position, SPOT, "the same object, moved back")
	assert_eq(BoardTextWriter.write(level).count('"windmill"'), 1)


func test_the_property_fields_edit_a_windmill_with_undo() -> void:
	var level := _open()
	session.set_tool(BoardEditSession.Tool.WINDMILL)
	_click(SPOT)
	var item := BoardItems.make(BoardItems.Kind.WINDMILL, 0)
	var fields := ItemProperties.values_of(level, item)
	assert_eq(fields.keys(), ["x", "y", "blades", "length", "free", "speed"])
	session.commit(ItemProperties.action_for(level, item, "blades", 6.0))
	session.commit(ItemProperties.action_for(level, item, "free", 1.0))
	assert_eq(level.windmills[0].blades, 6)
	assert_true(level.windmills[0].free_spin)
	assert_true(ItemProperties.values_of(level, item).has("friction"), "a free wheel's friction")
	session.commit(ItemProperties.action_for(level, item, "friction", 90.0))
	var text := BoardTextWriter.write(level)
	assert_string_contains(text, '"blades": 6, "length": 22, "friction": 90}}')
	session.history.undo()
	session.history.undo()
	assert_false(level.windmills[0].free_spin)
	assert_eq(level.windmills[0].friction, WindmillSpec.DEFAULT_FRICTION)
	session.history.undo()
	assert_eq(level.windmills[0].blades, 4)


func test_erase_removes_a_windmill_and_its_id_is_not_reused() -> void:
	var level := _open()
	session.set_tool(BoardEditSession.Tool.WINDMILL)
	_click(SPOT)
	_click(SPOT + Vector2(100, 0))
	session.set_tool(BoardEditSession.Tool.ERASE)
	_click(SPOT + Vector2(100, 5))
	assert_eq(level.windmills.size(), 1)
	assert_eq(level.windmills[0].position, SPOT)
	session.set_tool(BoardEditSession.Tool.WINDMILL)
	_click(SPOT + Vector2(0, 100))
	assert_eq(ItemNames.name_of(level, BoardItems.make(BoardItems.Kind.WINDMILL, 1)), "Windmill 3")
	session.history.undo()
	session.history.undo()
	assert_eq(level.windmills.size(), 2, "erase undone")
