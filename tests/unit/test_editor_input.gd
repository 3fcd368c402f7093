extends GutTest
## The board tool owns the input over the board while a board is edited: keys it has no use
## for, right-clicks, drags on empty board and arrows with nothing selected never reach
## Godot's 2D tools; zoom, pan, Godot's Ctrl shortcuts and F-keys still do. A click that
## only brings the focus back performs no action.

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const BoardInput := preload("res://addons/board_editor/board_input.gd")
const TestEditorTools := preload("res://tests/unit/test_editor_tools.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")

var session: BoardEditSession
var input: BoardInput


func start(level: BoardLevel) -> void:
	session = BoardEditSession.new(level)
	input = BoardInput.new(session)


func pins(count: int) -> BoardLevel:
	var helper := TestEditorTools.new()
	var level := helper.pins(count)
	helper.free()
	return level


func key(code: Key, ctrl := false) -> bool:
	var event := InputEventKey.new()
	event.keycode = code
	event.pressed = true
	event.ctrl_pressed = ctrl
	return input.handle(event, Transform2D.IDENTITY)


func click(at: Vector2) -> void:
	var event := InputEventMouseButton.new()
	event.button_index = MOUSE_BUTTON_LEFT
	event.position = at
	for down: bool in [true, false]:
		event.pressed = down
		input.handle(event, Transform2D.IDENTITY)


func release_key(code: Key) -> bool:
	var event := InputEventKey.new()
	event.keycode = code
	event.pressed = false
	return input.handle(event, Transform2D.IDENTITY)


func right_click(at: Vector2) -> Array[bool]:
	var used: Array[bool] = []
	for down: bool in [true, false]:
		var event := InputEventMouseButton.new()
		event.button_index = MOUSE_BUTTON_RIGHT
		event.pressed = down
		event.position = at
		used.append(input.handle(event, Transform2D.IDENTITY))
	return used


func test_the_board_tool_keeps_every_input_over_the_board_from_godot() -> void:
	start(pins(2))
	for code: Key in [KEY_W, KEY_E, KEY_R, KEY_V, KEY_S, KEY_G, KEY_Z, KEY_SPACE]:
		assert_true(key(code), "%s is the board tool's, not Godot's" % OS.get_keycode_string(code))
		assert_true(release_key(code), "and so is its release")
	assert_eq(session.level.pins.size(), 2)
	session.select([])
	assert_true(key(KEY_LEFT), "arrows with nothing selected never move the board node")
	assert_eq(right_click(Vector2(300, 300)), [true, true] as Array[bool], "no Godot menu")
	var motion := InputEventMouseMotion.new()
	motion.position = Vector2(300, 300)
	motion.button_mask = MOUSE_BUTTON_MASK_LEFT
	for tool: int in session.available_tools():
		session.set_tool(tool)
		var button := InputEventMouseButton.new()
		button.button_index = MOUSE_BUTTON_LEFT
		button.pressed = true
		button.position = Vector2(session.level.size.x - 4.0, 4.0)  # empty corner of the board
		assert_true(
			input.handle(button, Transform2D.IDENTITY), "press on empty board, tool %d" % tool
		)
		assert_true(
			input.handle(motion, Transform2D.IDENTITY), "drag on empty board, tool %d" % tool
		)
		button.pressed = false
		assert_true(input.handle(button, Transform2D.IDENTITY), "release, tool %d" % tool)
		input.active_tool().cancel()


func test_godot_keeps_navigation_and_its_own_shortcuts() -> void:
	start(pins(1))
	assert_false(key(KEY_Z, true), "Ctrl+Z is the editor's undo")
	assert_false(key(KEY_N, true), "Ctrl+N is the editor's new scene")
	assert_false(key(KEY_F5), "F5 runs the project")
	var wheel := InputEventMouseButton.new()
	wheel.button_index = MOUSE_BUTTON_WHEEL_UP
	wheel.pressed = true
	wheel.position = Vector2(300, 300)
	assert_false(input.handle(wheel, Transform2D.IDENTITY), "the wheel zooms")


func test_a_click_far_off_the_board_keeps_the_board_and_clears_the_selection() -> void:
	start(pins(2))
	session.select([BoardItems.make(BoardItems.Kind.PIN, 0)] as Array[Vector2i])
	var far := InputEventMouseButton.new()
	far.button_index = MOUSE_BUTTON_LEFT
	far.position = Vector2(-500, -500)
	for down: bool in [true, false]:
		far.pressed = down
		assert_true(input.handle(far, Transform2D.IDENTITY), "never Godot's: it would deselect")
	assert_eq(session.selection.size(), 0, "the Select tool's empty click clears the selection")
	session.set_tool(BoardEditSession.Tool.PIN)
	for down: bool in [true, false]:
		far.pressed = down
		assert_true(input.handle(far, Transform2D.IDENTITY), "the pin tool's press is kept too")
	assert_eq(session.level.pins.size(), 2, "but places nothing off the board")


func test_copy_paste_and_duplicate_with_nothing_selected_stay_with_the_board() -> void:
	start(pins(2))
	for code: Key in [KEY_C, KEY_V, KEY_D]:
		assert_true(key(code, true), "Ctrl+%s never reaches Godot" % OS.get_keycode_string(code))
	assert_eq(session.level.pins.size(), 2, "and changes nothing")


func test_a_click_that_brings_the_focus_back_does_nothing_else() -> void:
	start(pins(0))
	session.set_tool(BoardEditSession.Tool.POCKET)
	var button := InputEventMouseButton.new()
	button.button_index = MOUSE_BUTTON_LEFT
	button.position = Vector2(300, 400)
	for down: bool in [true, false]:
		button.pressed = down
		assert_true(input.handle(button, Transform2D.IDENTITY, false), "the focus click is used")
	assert_eq(session.level.pockets.size(), 0, "but it adds no pocket")
	click(Vector2(300, 400))
	assert_eq(session.level.pockets.size(), 1, "the next click does")


func test_a_box_drag_round_pins_placed_above_the_board_stays_in_the_tool() -> void:
	var level := pins(2)
	level.pins = PackedVector2Array([Vector2(100, -90), Vector2(130, -95)])
	start(level)
	var press := InputEventMouseButton.new()
	press.button_index = MOUSE_BUTTON_LEFT
	press.pressed = true
	press.position = Vector2(80, -120)  # above the board, beside the pins placed there
	assert_true(input.handle(press, Transform2D.IDENTITY), "the press is the select tool's")
	var motion := InputEventMouseMotion.new()
	motion.position = Vector2(150, -70)
	motion.button_mask = MOUSE_BUTTON_MASK_LEFT
	assert_true(input.handle(motion, Transform2D.IDENTITY))
	press.pressed = false
	press.position = motion.position
	assert_true(input.handle(press, Transform2D.IDENTITY))
	assert_eq(session.selection.size(), 2, "the box picked both pins")
	assert_false(input.is_over_board(Vector2(80, -400)), "far from board and items: Godot's")


func test_the_digits_godot_zooms_on_are_the_plugins_to_take_first() -> void:
	# Godot's 2D view runs its zoom shortcuts (1 = 100 %, 2 = 200 %, Shift+1 = 50 %) after
	# the plugin whatever the plugin answered, so the plugin takes these keys in _input.
	for code: Key in [KEY_1, KEY_2, KEY_3, KEY_5, KEY_KP_2]:
		var digit := InputEventKey.new()
		digit.keycode = code
		digit.pressed = true
		assert_true(BoardInput.is_view_zoom_key(digit), OS.get_keycode_string(code))
		digit.shift_pressed = true
		assert_true(BoardInput.is_view_zoom_key(digit), "Shift+" + OS.get_keycode_string(code))
	var letter := InputEventKey.new()
	letter.keycode = KEY_Q
	assert_false(BoardInput.is_view_zoom_key(letter), "tool keys go the usual way")
	var save := InputEventKey.new()
	save.keycode = KEY_1
	save.ctrl_pressed = true
	assert_false(BoardInput.is_view_zoom_key(save), "Ctrl+1 stays Godot's")
