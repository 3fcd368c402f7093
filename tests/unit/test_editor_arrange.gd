extends GutTest
## Peg curves, align and distribute, layers and the red ghost: each edit one undo step.

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const BoardInput := preload("res://addons/board_editor/board_input.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const CurvePins := preload("res://addons/board_editor/core/curve_pins.gd")
const HitTest := preload("res://addons/board_editor/core/hit_test.gd")
const PropertyPanel := preload("res://addons/board_editor/ui/property_panel.gd")
const NewBoard := preload("res://addons/board_editor/core/new_board.gd")
const AddItemsAction := preload("res://addons/board_editor/actions/add_items_action.gd")


func _pachinko(pins: PackedVector2Array) -> BoardEditSession:
	var session := BoardEditSession.new(NewBoard.make(BoardLevel.Kind.PACHINKO))
	var data := BoardItems.empty_set()
	data["pins"] = pins
	session.commit(AddItemsAction.new(session.level, data, "Add"))
	return session


func _mouse(input: BoardInput, at: Vector2, state: int) -> void:
	var event: InputEventMouse
	if state == 1:
		event = InputEventMouseMotion.new()
		(event as InputEventMouseMotion).button_mask = MOUSE_BUTTON_MASK_LEFT
	else:
		event = InputEventMouseButton.new()
		(event as InputEventMouseButton).button_index = MOUSE_BUTTON_LEFT
		(event as InputEventMouseButton).pressed = state == 0
	event.position = at
	input.handle(event, Transform2D.IDENTITY)


func test_curve_pins_by_count_and_by_spacing() -> void:
	var path := PackedVector2Array([Vector2(0, 0), Vector2(100, 0), Vector2(100, 90)])
	var by_count := CurvePins.along(path, 20, 0.0)
	assert_eq(by_count.size(), 20)
	assert_eq(by_count[0], Vector2(0, 0))
	assert_true(by_count[19].is_equal_approx(Vector2(100, 90)), "the last pin ends the curve")
	assert_true(by_count[10].is_equal_approx(Vector2(100, 0)), "evenly along the length")
	var by_spacing := CurvePins.along(path, 0, 19.0)
	assert_eq(by_spacing.size(), 11, "one every 19 px along 190 px")


func test_drawing_a_20_peg_curve_is_one_undo_step() -> void:
	var session := _pachinko(PackedVector2Array())
	var input := BoardInput.new(session)
	session.set_tool(BoardEditSession.Tool.CURVE)
	session.curve["count"] = 20
	_mouse(input, Vector2(200, 200), 0)
	for k in range(1, 21):
		var t := float(k) / 20.0
		_mouse(input, Vector2(200 + 300 * t, 200 + 120 * sin(t * PI)), 1)
	_mouse(input, Vector2(500, 200), 2)
	assert_eq(session.level.pins.size(), 20, "twenty pins along the curve")
	assert_eq(session.selection.size(), 20, "the new pins are selected")
	assert_eq(session.history.names()[-1], "Add a 20-pin curve")
	session.history.undo()
	assert_eq(session.level.pins.size(), 0, "one undo takes the whole curve back")


func test_a_mirrored_curve_is_named_by_every_pin_it_adds() -> void:
	var session := _pachinko(PackedVector2Array())
	var input := BoardInput.new(session)
	session.set_tool(BoardEditSession.Tool.CURVE)
	session.set_mirror(true)
	session.curve["count"] = 13
	_mouse(input, Vector2(100, 200), 0)
	for k in range(1, 11):
		_mouse(input, Vector2(100 + 20 * k, 200 + 4 * k), 1)
	_mouse(input, Vector2(300, 240), 2)
	assert_eq(session.level.pins.size(), 26, "13 pins and their 13 mirror twins")
	assert_eq(session.history.names()[-1], "Add a 26-pin curve", "History says what was added")


func test_align_a_row_and_distribute_it() -> void:
	var pins := PackedVector2Array([Vector2(100, 103), Vector2(180, 97), Vector2(150, 110)])
	var session := _pachinko(pins)
	var panel: PropertyPanel = add_child_autofree(PropertyPanel.new())
	panel.bind(session)
	var all: Array[Vector2i] = []
	for i in 3:
		all.append(BoardItems.make(BoardItems.Kind.PIN, i))
	session.select(all)
	panel.align("top")
	for i in 3:
		assert_eq(session.level.pins[i].y, 97.0, "pin %d on the top line" % i)
	panel.distribute("x")
	assert_eq(session.level.pins[2].x, 140.0, "the middle pin halfway between the ends")
	session.history.undo()
	assert_eq(session.level.pins[2].x, 150.0, "distribute is one step")
	session.history.undo()
	assert_eq(session.level.pins[0].y, 103.0, "align is one step")


func test_hidden_and_locked_layers_cannot_be_picked() -> void:
	var session := _pachinko(PackedVector2Array([Vector2(300, 300)]))
	var input := BoardInput.new(session)
	session.select([BoardItems.make(BoardItems.Kind.PIN, 0)] as Array[Vector2i])
	session.set_layer("Pins", true, false)
	assert_eq(session.selection.size(), 0, "hiding the pins drops them from the selection")
	_mouse(input, Vector2(300, 300), 0)
	_mouse(input, Vector2(300, 300), 2)
	assert_eq(session.selection.size(), 0, "a hidden pin cannot be clicked")
	session.set_layer("Pins", false, true)
	session.set_tool(BoardEditSession.Tool.ERASE)
	_mouse(input, Vector2(300, 300), 0)
	_mouse(input, Vector2(300, 300), 2)
	assert_eq(session.level.pins.size(), 1, "a locked pin cannot be erased")
	session.set_layer("Pins", false, false)
	_mouse(input, Vector2(300, 300), 0)
	_mouse(input, Vector2(300, 300), 2)
	assert_eq(session.level.pins.size(), 0, "unlocked, it can")


func test_ghost_turns_red_where_a_pin_would_crowd_another() -> void:
	var session := _pachinko(PackedVector2Array([Vector2(300, 300)]))
	assert_true(HitTest.crowds_pin(session.level, Vector2(304, 300)), "on top of a pin")
	assert_true(HitTest.crowds_pin(session.level, Vector2(310, 300)), "a gap a ball sticks in")
	assert_false(HitTest.crowds_pin(session.level, Vector2(340, 300)), "room to spare")
