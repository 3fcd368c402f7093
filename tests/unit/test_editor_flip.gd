extends GutTest
## Mirroring existing work: flip a selection (H), add its mirror image on the other half
## (Shift+M), Ctrl+D in mirror mode, and the erase brush sweeping the whole stroke.

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const BoardInput := preload("res://addons/board_editor/board_input.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const HitTest := preload("res://addons/board_editor/core/hit_test.gd")
const PropertyPanel := preload("res://addons/board_editor/ui/property_panel.gd")
const TestEditorActions := preload("res://tests/unit/test_editor_actions.gd")

var session: BoardEditSession
var input: BoardInput


func start(level: BoardLevel) -> void:
	session = BoardEditSession.new(level)
	input = BoardInput.new(session)


func with_pins(points: Array[Vector2]) -> BoardLevel:
	var level := TestEditorActions.pachinko()
	var pins := PackedVector2Array(points)
	level.pins = pins
	var owners := PackedInt32Array()
	owners.resize(pins.size())
	owners.fill(-1)
	level.pin_pocket = owners
	var special := PackedByteArray()
	special.resize(pins.size())
	level.pin_special = special
	return level


func key(code: Key, ctrl := false, shift := false) -> bool:
	var event := InputEventKey.new()
	event.keycode = code
	event.pressed = true
	event.ctrl_pressed = ctrl
	event.shift_pressed = shift
	return input.handle(event, Transform2D.IDENTITY)


func mouse(at: Vector2, down: Variant = null) -> void:
	var event: InputEvent
	if down == null:
		var motion := InputEventMouseMotion.new()
		motion.position = at
		motion.button_mask = MOUSE_BUTTON_MASK_LEFT
		event = motion
	else:
		var button := InputEventMouseButton.new()
		button.button_index = MOUSE_BUTTON_LEFT
		button.pressed = down
		button.position = at
		event = button
	input.handle(event, Transform2D.IDENTITY)


func pin_items(indices: Array[int]) -> Array[Vector2i]:
	var items: Array[Vector2i] = []
	for i in indices:
		items.append(BoardItems.make(BoardItems.Kind.PIN, i))
	return items


func test_h_flips_the_selection_about_its_centre_in_one_step() -> void:
	var level := with_pins([Vector2(100, 100), Vector2(120, 140), Vector2(160, 100)])
	level.windmills = (
		[WindmillSpec.driven(Vector2(200, 200), 4, 22.0, 120.0)] as Array[WindmillSpec]
	)
	start(level)
	session.select(pin_items([0, 1, 2]))
	assert_true(key(KEY_H))
	assert_eq(
		level.pins,
		PackedVector2Array([Vector2(160, 100), Vector2(140, 140), Vector2(100, 100)]),
		"each pin lands at its reflection about the selection's middle (x 130)"
	)
	assert_eq(session.history.names(), PackedStringArray(["Flip 3 items left to right"]))
	var ids := level.pin_ids.duplicate()
	key(KEY_H)
	assert_eq(level.pins[1], Vector2(120, 140), "flipped twice: back where it was")
	assert_eq(level.pin_ids, ids, "the pins keep their ids")
	session.history.undo()
	assert_eq(level.pins[1], Vector2(140, 140), "one undo flips all three back")
	session.select([BoardItems.make(BoardItems.Kind.WINDMILL, 0)] as Array[Vector2i])
	key(KEY_H)
	assert_eq(level.windmills[0].speed, -120.0, "a flipped wheel turns back")


func test_flipping_a_wall_reflects_both_ends() -> void:
	var maze := TestEditorActions.maze()
	maze.walls = PackedVector2Array([Vector2(35, 35), Vector2(105, 70)])
	start(maze)
	session.select([BoardItems.make(BoardItems.Kind.WALL, 0)] as Array[Vector2i])
	key(KEY_H)
	assert_eq(maze.walls, PackedVector2Array([Vector2(105, 35), Vector2(35, 70)]))


func test_flip_in_mirror_mode_flips_the_twins_so_the_board_stays_symmetrical() -> void:
	start(with_pins([Vector2(100, 100), Vector2(140, 120), Vector2(500, 100), Vector2(460, 120)]))
	session.set_mirror(true)
	session.select(pin_items([0, 1]))
	key(KEY_H)
	var pins := session.level.pins
	assert_eq(pins[0], Vector2(140, 100))
	assert_eq(pins[1], Vector2(100, 120))
	assert_eq(pins[2], Vector2(460, 100), "the twin is still the mirror image of pin 0")
	assert_eq(pins[3], Vector2(500, 120))
	assert_eq(session.history.names().size(), 1, "one undo step for both halves")


func test_shift_m_adds_the_mirror_image_keeping_the_originals_and_existing_twins() -> void:
	start(with_pins([Vector2(100, 100), Vector2(150, 120), Vector2(500, 100), Vector2(300, 50)]))
	session.select(pin_items([0, 1, 3]))
	assert_true(key(KEY_M, false, true))
	assert_false(session.mirror_enabled, "Shift+M is a command, not the mirror toggle")
	assert_eq(
		session.level.pins,
		PackedVector2Array(
			(
				[Vector2(100, 100), Vector2(150, 120), Vector2(500, 100), Vector2(300, 50)]
				+ [Vector2(450, 120)]
			)
		),
		"only pin 1 lacked its twin; pin 0 has one and pin 3 is on the axis"
	)
	assert_eq(session.selection.size(), 4, "the originals and the new twin are selected")
	assert_eq(session.history.names(), PackedStringArray(["Mirror 1 item to the other half"]))
	assert_true(key(KEY_M, false, true))
	assert_eq(session.level.pins.size(), 5, "a second Shift+M doubles nothing")


func test_mirror_to_the_other_half_copies_pockets_walls_and_windmills() -> void:
	var level := TestEditorActions.pachinko()
	var wheel := WindmillSpec.driven(Vector2(200, 200), 4, 22.0, 120.0)
	level.windmills = [wheel] as Array[WindmillSpec]
	start(level)
	session.select([BoardItems.make(BoardItems.Kind.WINDMILL, 0)] as Array[Vector2i])
	key(KEY_M, false, true)
	assert_eq(level.windmills.size(), 2)
	assert_eq(level.windmills[1].position, Vector2(400, 200))
	assert_eq(level.windmills[1].speed, -wheel.speed, "the twin turns the other way")
	var maze := TestEditorActions.maze()
	maze.walls = PackedVector2Array([Vector2(35, 35), Vector2(105, 70)])
	start(maze)
	session.select([BoardItems.make(BoardItems.Kind.WALL, 0)] as Array[Vector2i])
	key(KEY_M, false, true)
	assert_eq(maze.walls.slice(2), PackedVector2Array([Vector2(315, 35), Vector2(245, 70)]))


func test_ctrl_d_in_mirror_mode_duplicates_the_twin_the_other_way() -> void:
	start(with_pins([Vector2(100, 100), Vector2(500, 100)]))
	session.set_mirror(true)
	session.select(pin_items([0]))
	assert_true(key(KEY_D, true))
	assert_eq(
		session.level.pins,
		PackedVector2Array(
			[Vector2(100, 100), Vector2(500, 100), Vector2(120, 100), Vector2(480, 100)]
		)
	)
	assert_eq(session.history.names().size(), 1)
	session.select(pin_items([0, 1]))
	key(KEY_D, true)
	assert_eq(session.level.pins.size(), 6, "both twins selected: each copy comes once")
	assert_eq(session.level.pins[4], Vector2(120, 100))
	assert_eq(session.level.pins[5], Vector2(480, 100))


func test_erase_drag_along_a_20_pin_curve_erases_all_20() -> void:
	var curve: Array[Vector2] = []
	for i in 20:
		var x := 110.0 + i * 20.0
		curve.append(Vector2(x, 300.0 + 0.0005 * (x - 300.0) * (x - 300.0)))
	start(with_pins(curve))
	key(KEY_X)
	# A quick drag: the mouse reports every sixth pin only.
	mouse(curve[0], true)
	for i in [6, 12, 18]:
		mouse(curve[i])
	mouse(curve[19])
	mouse(curve[19], false)
	assert_eq(session.level.pins.size(), 0, "every pin the stroke passed over is gone")
	assert_eq(session.history.names().size(), 1, "in one undo step")


func test_the_brush_sweeps_a_capsule_between_mouse_events() -> void:
	var level := with_pins([Vector2(100, 100), Vector2(150, 109), Vector2(150, 120)])
	level.kind = BoardLevel.Kind.PACHINKO
	var hit := HitTest.along(level, Vector2(50, 100), Vector2(250, 100), 6.0)
	assert_eq(hit, pin_items([0, 1]), "pin 1 is 9 px off the stroke: 3 px radius + 6 brush")
	var maze := TestEditorActions.maze()
	maze.walls = PackedVector2Array([Vector2(150, 20), Vector2(150, 200)])
	var crossed := HitTest.along(maze, Vector2(100, 100), Vector2(200, 100), 1.0)
	assert_eq(
		crossed, [BoardItems.make(BoardItems.Kind.WALL, 0)], "a wall crossed far from its ends"
	)


func test_align_and_space_name_their_history_step_in_words() -> void:
	assert_eq(PropertyPanel.history_name("center_y"), "Align middle")
	assert_eq(PropertyPanel.history_name("center_x"), "Align centre")
	assert_eq(PropertyPanel.history_name("x"), "Space across")
