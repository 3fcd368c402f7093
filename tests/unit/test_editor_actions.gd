extends GutTest
## The board editor's actions: each one's do / undo / redo against a real BoardLevel.

const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const ActionHistory := preload("res://addons/board_editor/core/action_history.gd")
const AddItemsAction := preload("res://addons/board_editor/actions/add_items_action.gd")
const PatternAction := preload("res://addons/board_editor/actions/pattern_action.gd")
const PocketAction := preload("res://addons/board_editor/actions/pocket_action.gd")
const WallAction := preload("res://addons/board_editor/actions/wall_action.gd")
const MoveItemsAction := preload("res://addons/board_editor/actions/move_items_action.gd")
const DeleteItemsAction := preload("res://addons/board_editor/actions/delete_items_action.gd")
const SetPropertiesAction := preload("res://addons/board_editor/actions/set_properties_action.gd")
const EditPocketAction := preload("res://addons/board_editor/actions/edit_pocket_action.gd")


static func pachinko() -> BoardLevel:
	var level := BoardLevel.new()
	level.kind = BoardLevel.Kind.PACHINKO
	level.size = Vector2(600, 600)
	level.ring_center = Vector2(300, 300)
	level.ring_radius = 280.0
	level.pin_radius = 3.0
	level.ball_radius = 6.0
	return level


static func maze() -> BoardLevel:
	var level := BoardLevel.new()
	level.kind = BoardLevel.Kind.MAZE
	level.grid_cols = 10
	level.grid_rows = 9
	level.path_width = 25.0
	level.wall_width = 10.0
	level.size = Vector2(350, 315)
	level.ball_radius = 5.0
	level.hole_radius = 9.0
	level.goal_center = Vector2(175, 157.5)
	level.goal_radius = 32.5
	return level


## Runs `action` through do, undo and redo, checking the board after each step.
func check_round_trip(level: BoardLevel, action: RefCounted, read: Callable) -> void:
	# Text copies: packed arrays are shared by reference, so keeping them would compare the
	# board with itself.
	var before := var_to_str(read.call(level))
	var history := ActionHistory.new()
	history.commit(action)
	var after := var_to_str(read.call(level))
	assert_ne(after, before, "do() changed the board")
	history.undo()
	assert_eq(var_to_str(read.call(level)), before, "undo() restored the board")
	history.redo()
	assert_eq(var_to_str(read.call(level)), after, "redo() applied the same change again")


static func pins_of(level: BoardLevel) -> Array:
	return [level.pins, level.pin_pocket, level.pin_special, level.pockets.size()]


func test_add_pins_round_trip() -> void:
	var level := pachinko()
	var data := BoardItems.empty_set()
	data["pins"] = PackedVector2Array([Vector2(100, 100), Vector2(120, 100)])
	var action := AddItemsAction.new(level, data, "Add pin")
	check_round_trip(level, action, pins_of)
	assert_eq(level.pins.size(), 2)
	assert_eq(level.pin_pocket, PackedInt32Array([-1, -1]))
	assert_eq(action.added.size(), 2, "added lists the new pins")


func test_pattern_action_round_trip() -> void:
	var level := pachinko()
	var settings := {"kind": "row", "count": 5, "spacing": 20.0}
	check_round_trip(level, PatternAction.new(level, settings, Vector2(300, 200)), pins_of)
	assert_eq(level.pins.size(), 5)


func test_pocket_action_stamps_rim_and_special_pin() -> void:
	var level := pachinko()
	check_round_trip(level, PocketAction.new(level, Vector2(300, 400), 30, 24, 15), pins_of)
	assert_eq(level.pockets.size(), 1)
	assert_eq(level.pockets[0].payout, 15)
	var stamp := PocketStamp.rim_pins(level.pockets[0], level.pin_radius, level.ball_radius)
	assert_eq(level.pins, stamp, "the pins are exactly PocketStamp's")
	assert_eq(level.pin_special.count(1), 1, "one special pin")
	assert_eq(level.pins[level.pin_special.find(1)], Vector2(300, 424), "at the bottom")
	for owner in level.pin_pocket:
		assert_eq(owner, 0)


func test_redo_brings_back_the_same_pocket_resource() -> void:
	var level := pachinko()
	var history := ActionHistory.new()
	history.commit(PocketAction.new(level, Vector2(300, 400), 30, 24, 15))
	var spec: PocketSpec = level.pockets[0]
	history.undo()
	history.redo()
	assert_same(level.pockets[0], spec)


func test_wall_action_round_trip() -> void:
	var level := maze()
	var read := func(board: BoardLevel) -> PackedVector2Array: return board.walls
	check_round_trip(level, WallAction.new(level, Vector2(35, 35), Vector2(105, 35)), read)
	assert_eq(level.walls, PackedVector2Array([Vector2(35, 35), Vector2(105, 35)]))


func test_move_takes_pocket_pins_along() -> void:
	var level := pachinko()
	var history := ActionHistory.new()
	history.commit(PocketAction.new(level, Vector2(300, 400), 30, 24, 15))
	history.commit(
		PatternAction.new(level, {"kind": "row", "count": 2, "spacing": 40.0}, Vector2(300, 200))
	)
	var pocket_pins := BoardItems.pocket_pins(level, 0)
	var first_rim := level.pins[pocket_pins[0]]
	var items: Array[Vector2i] = [BoardItems.make(BoardItems.Kind.POCKET, 0)]
	var move := MoveItemsAction.new(level, items, Vector2(10, -5))
	check_round_trip(
		level,
		move,
		func(board: BoardLevel) -> Array: return [board.pins, board.pockets[0].position]
	)
	assert_eq(level.pockets[0].position, Vector2(310, 395))
	assert_eq(level.pins[pocket_pins[0]], first_rim + Vector2(10, -5))
	assert_eq(level.pins[level.pins.size() - 1], Vector2(320, 200), "field pins stay put")


func test_move_preview_then_commit_is_one_step() -> void:
	var level := maze()
	level.holes = PackedVector2Array([Vector2(50, 50)])
	var items: Array[Vector2i] = [BoardItems.make(BoardItems.Kind.HOLE, 0)]
	var move := MoveItemsAction.new(level, items, Vector2.ZERO)
	for step in 5:
		move.preview(Vector2(step * 3, step))
	assert_eq(level.holes[0], Vector2(62, 54), "preview shows the latest offset only")
	var history := ActionHistory.new()
	history.commit(move, true)
	history.undo()
	assert_eq(level.holes[0], Vector2(50, 50), "one undo takes the whole drag back")
	history.redo()
	assert_eq(level.holes[0], Vector2(62, 54))


func test_delete_renumbers_pocket_pins() -> void:
	var level := pachinko()
	var history := ActionHistory.new()
	history.commit(PocketAction.new(level, Vector2(200, 400), 30, 24, 5))
	history.commit(PocketAction.new(level, Vector2(400, 400), 30, 24, 9))
	var second_pins := BoardItems.pocket_pins(level, 1).size()
	var items: Array[Vector2i] = [BoardItems.make(BoardItems.Kind.POCKET, 0)]
	check_round_trip(level, DeleteItemsAction.new(level, items), pins_of)
	assert_eq(level.pockets.size(), 1)
	assert_eq(level.pockets[0].payout, 9, "the other pocket stays")
	assert_eq(BoardItems.pocket_pins(level, 0).size(), second_pins, "its pins now point at index 0")
	assert_eq(level.pins.size(), second_pins)


func test_delete_walls_holes_and_starts() -> void:
	var level := maze()
	level.walls = PackedVector2Array(
		[Vector2(0, 0), Vector2(35, 0), Vector2(0, 35), Vector2(0, 70)]
	)
	level.holes = PackedVector2Array([Vector2(10, 10), Vector2(20, 20)])
	level.ball_starts = PackedVector2Array([Vector2(17, 17)])
	var items: Array[Vector2i] = [
		BoardItems.make(BoardItems.Kind.WALL, 0),
		BoardItems.make(BoardItems.Kind.HOLE, 1),
		BoardItems.make(BoardItems.Kind.START, 0)
	]
	var read := func(board: BoardLevel) -> Array:
		return [board.walls, board.holes, board.ball_starts]
	check_round_trip(level, DeleteItemsAction.new(level, items), read)
	assert_eq(level.walls, PackedVector2Array([Vector2(0, 35), Vector2(0, 70)]))
	assert_eq(level.holes, PackedVector2Array([Vector2(10, 10)]))
	assert_eq(level.ball_starts.size(), 0)


func test_set_properties_round_trip_and_preview() -> void:
	var level := pachinko()
	var action := SetPropertiesAction.new(level, {"ring_radius": 250.0}, "Resize ring")
	action.preview({"ring_radius": 260.0})
	assert_eq(level.ring_radius, 260.0)
	var history := ActionHistory.new()
	history.commit(action, true)
	history.undo()
	assert_eq(level.ring_radius, 280.0)
	history.redo()
	assert_eq(level.ring_radius, 260.0)


func test_edit_pocket_restamps_pins() -> void:
	var level := pachinko()
	var history := ActionHistory.new()
	history.commit(PocketAction.new(level, Vector2(300, 400), 30, 24, 15))
	var narrow := level.pins.size()
	check_round_trip(level, EditPocketAction.new(level, 0, 44, 40, 3), pins_of)
	assert_eq(level.pockets[0].width, 44.0)
	assert_eq(level.pockets[0].payout, 3)
	assert_gt(level.pins.size(), narrow, "a bigger pocket has more rim pins")
	var stamp := PocketStamp.rim_pins(level.pockets[0], level.pin_radius, level.ball_radius)
	assert_eq(level.pins, stamp)
	history.commit(EditPocketAction.new(level, 0, 50, 50, 1))
	history.undo()
	assert_eq(level.pockets[0].width, 44.0, "undo restores the pocket's numbers too")
	assert_eq(level.pins, stamp, "and its pins")
