extends GutTest
## The editor's tools and keys driven the way the plugin drives them: events in, actions
## committed to a history, the board and the selection checked after each step.

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const BoardInput := preload("res://addons/board_editor/board_input.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const BoardOverlay := preload("res://addons/board_editor/ui/board_overlay.gd")
const TestEditorActions := preload("res://tests/unit/test_editor_actions.gd")

var session: BoardEditSession
var input: BoardInput


func start(level: BoardLevel) -> void:
	session = BoardEditSession.new(level)
	input = BoardInput.new(session)


func click(at: Vector2, shift := false, ctrl := false) -> void:
	press(at, true, shift, ctrl)
	press(at, false, shift, ctrl)


func press(at: Vector2, down: bool, shift := false, ctrl := false) -> void:
	var event := InputEventMouseButton.new()
	event.button_index = MOUSE_BUTTON_LEFT
	event.pressed = down
	event.position = at
	event.shift_pressed = shift
	event.ctrl_pressed = ctrl
	input.handle(event, Transform2D.IDENTITY)


func move(at: Vector2) -> void:
	var event := InputEventMouseMotion.new()
	event.position = at
	event.button_mask = MOUSE_BUTTON_MASK_LEFT
	input.handle(event, Transform2D.IDENTITY)


func key(code: Key, ctrl := false, shift := false) -> bool:
	var event := InputEventKey.new()
	event.keycode = code
	event.pressed = true
	event.ctrl_pressed = ctrl
	event.shift_pressed = shift
	return input.handle(event, Transform2D.IDENTITY)


func pins(count: int) -> BoardLevel:
	var level := TestEditorActions.pachinko()
	for i in count:
		level.pins.append(Vector2(100 + i * 20, 100))
	level.pins = level.pins
	level.pin_pocket.resize(count)
	level.pin_pocket.fill(-1)
	level.pin_special.resize(count)
	return level


func test_pin_tool_places_a_snapped_pin_and_undo_removes_it() -> void:
	start(TestEditorActions.pachinko())
	assert_true(key(KEY_P), "P picks the pin tool")
	click(Vector2(103, 208))
	assert_eq(
		session.level.pins, PackedVector2Array([Vector2(100, 210)]), "snapped to the 10 px grid"
	)
	session.history.undo()
	assert_eq(session.level.pins.size(), 0)
	session.history.redo()
	assert_eq(session.level.pins.size(), 1)


func test_mirror_mode_places_both_halves() -> void:
	start(TestEditorActions.pachinko())
	key(KEY_M)
	assert_true(session.mirror_enabled)
	session.set_tool(BoardEditSession.Tool.PIN)
	click(Vector2(100, 100))
	assert_eq(session.level.pins, PackedVector2Array([Vector2(100, 100), Vector2(500, 100)]))


func test_click_shift_and_ctrl_selection() -> void:
	start(pins(3))
	click(Vector2(100, 100))
	assert_eq(session.selection, [Vector2i(0, 0)])
	click(Vector2(140, 100), true)
	assert_eq(session.selection, [Vector2i(0, 0), Vector2i(0, 2)], "shift adds")
	click(Vector2(100, 100), false, true)
	assert_eq(session.selection, [Vector2i(0, 2)], "ctrl toggles")


func test_box_select() -> void:
	start(pins(4))
	press(Vector2(90, 90), true)
	move(Vector2(145, 110))
	press(Vector2(145, 110), false)
	assert_eq(session.selection, [Vector2i(0, 0), Vector2i(0, 1), Vector2i(0, 2)])


func test_drag_moves_live_and_is_one_undo_step() -> void:
	start(pins(2))
	press(Vector2(100, 100), true)
	for step in 6:
		move(Vector2(100 + step * 4, 100 + step * 2))
	assert_eq(session.level.pins[0], Vector2(120, 110), "the preview follows the mouse, snapped")
	press(Vector2(120, 110), false)
	assert_eq(session.history.names().size(), 1, "a whole drag is one step")
	session.history.undo()
	assert_eq(session.level.pins[0], Vector2(100, 100))


func test_right_click_cancels_a_drag() -> void:
	start(pins(1))
	press(Vector2(100, 100), true)
	move(Vector2(150, 150))
	var cancel := InputEventMouseButton.new()
	cancel.button_index = MOUSE_BUTTON_RIGHT
	cancel.pressed = true
	assert_true(input.handle(cancel, Transform2D.IDENTITY))
	assert_eq(session.level.pins[0], Vector2(100, 100), "put back")
	assert_eq(session.history.names().size(), 0, "nothing recorded")


func test_delete_copy_paste_duplicate_and_nudge() -> void:
	start(pins(2))
	click(Vector2(100, 100))
	assert_true(key(KEY_C, true))
	move(Vector2(300, 300))
	assert_true(key(KEY_V, true))
	assert_eq(session.level.pins.size(), 3)
	assert_eq(session.level.pins[2], Vector2(300, 300), "pasted at the mouse")
	assert_eq(session.selection, [Vector2i(0, 2)], "the paste is selected")
	assert_true(key(KEY_D, true))
	assert_eq(session.level.pins[3], Vector2(320, 300), "duplicated beside it, a ball clear")
	assert_true(key(KEY_RIGHT))
	assert_eq(session.level.pins[3], Vector2(330, 300), "nudged one grid step")
	assert_true(key(KEY_DELETE))
	assert_eq(session.level.pins.size(), 3)
	assert_eq(session.selection.size(), 0)
	assert_true(key(KEY_DELETE), "Delete is always the board's, never the node's")


func test_wall_tool_drags_a_snapped_straight_wall() -> void:
	start(TestEditorActions.maze())
	assert_true(key(KEY_L))
	press(Vector2(37, 33), true)
	move(Vector2(100, 40))
	press(Vector2(108, 41), false)
	assert_eq(session.level.walls, PackedVector2Array([Vector2(35, 35), Vector2(105, 35)]))
	session.set_snap(false)
	press(Vector2(10, 10), true)
	press(Vector2(60, 70), false)
	assert_eq(session.level.walls[3], Vector2(60, 70), "free walls go where you drag")


func test_maze_places_holes_starts_and_goal_in_cells() -> void:
	start(TestEditorActions.maze())
	key(KEY_O)
	click(Vector2(40, 40))
	key(KEY_B)
	click(Vector2(80, 10))
	key(KEY_U)
	click(Vector2(200, 200))
	assert_eq(session.level.holes, PackedVector2Array([Vector2(52.5, 52.5)]))
	assert_eq(session.level.ball_starts, PackedVector2Array([Vector2(87.5, 17.5)]))
	assert_eq(session.level.goal_center, Vector2(192.5, 192.5))
	var tool := session.tool
	assert_true(key(KEY_P), "P is kept from Godot on a maze too")
	assert_eq(session.tool, tool, "but there is no pin tool on a maze")


func test_erase_tool_and_handles() -> void:
	start(pins(2))
	key(KEY_X)
	click(Vector2(120, 100))
	assert_eq(session.level.pins, PackedVector2Array([Vector2(100, 100)]))
	key(KEY_D)
	session.level.ring_radius = 280.0
	press(Vector2(300, 300), true)
	move(Vector2(320, 290))
	press(Vector2(320, 290), false)
	assert_eq(session.level.ring_center, Vector2(320, 290), "ring centre handle dragged")
	session.history.undo()
	assert_eq(session.level.ring_center, Vector2(300, 300))


func test_every_tool_and_the_overlay_draw_without_errors() -> void:
	var canvas: Control = add_child_autofree(Control.new())
	var painted := [0]
	for level: BoardLevel in [TestEditorActions.pachinko(), TestEditorActions.maze()]:
		start(level)
		session.level.pins = PackedVector2Array([Vector2(120, 100)])
		session.level.pin_pocket = PackedInt32Array([-1])
		session.level.pin_special = PackedByteArray([0])
		session.level.walls = PackedVector2Array([Vector2(35, 35), Vector2(105, 35)])
		session.select([Vector2i(0, 0), Vector2i(2, 0)] as Array[Vector2i])
		session.set_mirror(true)
		var issues: Array[BoardIssue] = [
			BoardIssue.new(BoardIssue.Severity.ERROR, "A test.", Vector2(50, 50))
		]
		for tool: int in session.available_tools():
			session.set_tool(tool)
			move(Vector2(121, 101))
			var paint := func() -> void:
				painted[0] += 1
				BoardOverlay.draw(
					canvas, Transform2D.IDENTITY, session, input.active_tool(), issues, 0
				)
			canvas.draw.connect(paint)
			canvas.queue_redraw()
			await get_tree().process_frame
			canvas.draw.disconnect(paint)
	# GUT fails the test on any engine or script error raised while drawing.
	# 11 pachinko tools, 7 maze tools and the floor arrow's (its row's).
	assert_eq(painted[0], 19, "every tool of both kinds drew its preview over the overlay")


func test_drag_erase_is_one_step() -> void:
	start(pins(4))
	key(KEY_X)
	press(Vector2(100, 100), true)
	move(Vector2(120, 100))
	move(Vector2(140, 100))
	assert_eq(session.level.pins.size(), 4, "marked, not yet gone")
	press(Vector2(140, 100), false)
	assert_eq(session.level.pins, PackedVector2Array([Vector2(160, 100)]))
	session.history.undo()
	assert_eq(session.level.pins.size(), 4, "one undo brings all three back")
