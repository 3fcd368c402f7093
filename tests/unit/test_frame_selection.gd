extends GutTest
## The board tool's Frame Selection: the area framed is the selected items' (the whole board
## with nothing selected), never the BoardNode's origin (0, 0) that Godot's own framing used.

const FrameSelection := preload("res://addons/board_editor/ui/frame_selection.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")


func _classic() -> BoardLevel:
	return BoardLoader.load_board("res://levels/pachinko/classic.board").level


func test_the_selected_items_are_framed_not_the_origin() -> void:
	var level := _classic()
	var a := BoardItems.make(BoardItems.Kind.PIN, 10)
	var b := BoardItems.make(BoardItems.Kind.PIN, 40)
	var area := FrameSelection.area(level, [a, b] as Array[Vector2i])
	var both := Rect2(level.pins[10], Vector2.ZERO).expand(level.pins[40])
	assert_true(area.encloses(both), "both pins in the frame")
	assert_almost_eq(area.get_center(), both.get_center(), Vector2.ONE * 0.01, "centred on them")
	assert_false(area.has_point(Vector2.ZERO), "not the node's origin: %s" % area)
	assert_almost_eq(
		area.size, both.grow(level.pin_radius + FrameSelection.MARGIN).size, Vector2.ONE * 0.01
	)


func test_nothing_selected_frames_the_whole_board() -> void:
	var level := _classic()
	var area := FrameSelection.area(level, [] as Array[Vector2i])
	assert_true(area.encloses(Rect2(Vector2.ZERO, level.size)))


func test_shift_f_is_the_frame_key() -> void:
	var key := InputEventKey.new()
	key.keycode = KEY_F
	key.pressed = true
	assert_false(FrameSelection.is_frame_key(key), "F alone is a tool key (Tulip)")
	key.shift_pressed = true
	assert_true(FrameSelection.is_frame_key(key))
	key.ctrl_pressed = true
	assert_false(FrameSelection.is_frame_key(key))
