extends GutTest
## The editor's static picking and snapping.

const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const HitTest := preload("res://addons/board_editor/core/hit_test.gd")
const Snapping := preload("res://addons/board_editor/core/snapping.gd")
const ActionHistory := preload("res://addons/board_editor/core/action_history.gd")
const PocketAction := preload("res://addons/board_editor/actions/pocket_action.gd")
const TestEditorActions := preload("res://tests/unit/test_editor_actions.gd")


func test_pick_finds_the_nearest_pin_within_tolerance() -> void:
	var level := TestEditorActions.pachinko()
	level.pins = PackedVector2Array([Vector2(100, 100), Vector2(110, 100)])
	level.pin_pocket = PackedInt32Array([-1, -1])
	level.pin_special = PackedByteArray([0, 0])
	assert_eq(HitTest.pick(level, Vector2(108, 101), 4.0), BoardItems.make(BoardItems.Kind.PIN, 1))
	assert_eq(HitTest.pick(level, Vector2(101, 99), 4.0), BoardItems.make(BoardItems.Kind.PIN, 0))
	assert_eq(HitTest.pick(level, Vector2(150, 150), 4.0), BoardItems.NONE)


func test_pocket_pins_pick_the_pocket() -> void:
	var level := TestEditorActions.pachinko()
	ActionHistory.new().commit(PocketAction.new(level, Vector2(300, 400), 30, 24, 5))
	var rim := level.pins[0]
	assert_eq(HitTest.pick(level, rim, 2.0), BoardItems.make(BoardItems.Kind.POCKET, 0))
	assert_eq(
		HitTest.pick(level, Vector2(300, 410), 2.0),
		BoardItems.make(BoardItems.Kind.POCKET, 0),
		"inside the cup"
	)


func test_pick_walls_by_distance_to_the_capsule() -> void:
	var level := TestEditorActions.maze()
	level.walls = PackedVector2Array([Vector2(0, 35), Vector2(105, 35)])
	assert_eq(HitTest.pick(level, Vector2(50, 41), 3.0), BoardItems.make(BoardItems.Kind.WALL, 0))
	assert_eq(HitTest.pick(level, Vector2(50, 50), 3.0), BoardItems.NONE)


func test_maze_goal_picked_only_near_its_middle() -> void:
	var level := TestEditorActions.maze()
	assert_eq(
		HitTest.pick(level, level.goal_center + Vector2(3, 0), 4.0),
		BoardItems.make(BoardItems.Kind.GOAL, 0)
	)
	assert_eq(HitTest.pick(level, level.goal_center + Vector2(30, 0), 4.0), BoardItems.NONE)


func test_box_selects_pockets_once_and_whole_walls_only() -> void:
	var level := TestEditorActions.maze()
	level.walls = PackedVector2Array(
		[Vector2(0, 0), Vector2(35, 0), Vector2(0, 0), Vector2(200, 0)]
	)
	level.holes = PackedVector2Array([Vector2(20, 20)])
	var found := HitTest.in_rect(level, Rect2(-5, -5, 60, 60))
	assert_true(found.has(BoardItems.make(BoardItems.Kind.WALL, 0)))
	assert_false(
		found.has(BoardItems.make(BoardItems.Kind.WALL, 1)), "half a wall in the box is not enough"
	)
	assert_true(found.has(BoardItems.make(BoardItems.Kind.HOLE, 0)))
	var board := TestEditorActions.pachinko()
	ActionHistory.new().commit(PocketAction.new(board, Vector2(300, 400), 30, 24, 5))
	assert_eq(
		HitTest.in_rect(board, Rect2(250, 380, 100, 80)),
		[BoardItems.make(BoardItems.Kind.POCKET, 0)]
	)


func test_handles_and_their_values() -> void:
	var level := TestEditorActions.pachinko()
	level.rail_start_deg = 40.0
	level.rail_end_deg = -105.0
	level.rail_width = 20.0
	var points := HitTest.handle_points(level)
	assert_eq(HitTest.pick_handle(level, points["ring_center"], 3.0), "ring_center")
	assert_eq(
		HitTest.pick_handle(level, points["rail_end_deg"] + Vector2(1, 1), 3.0), "rail_end_deg"
	)
	assert_almost_eq(
		float(HitTest.handle_value(level, "ring_radius", Vector2(300, 50))), 250.0, 0.001
	)
	var angle := float(
		HitTest.handle_value(
			level, "rail_end_deg", Vector2(300, 300) + Vector2.from_angle(deg_to_rad(250.0)) * 100
		)
	)
	assert_almost_eq(
		angle, -110.0, 0.001, "angles stay near their old value instead of jumping 360"
	)
	assert_almost_eq(
		float(HitTest.handle_value(level, "rail_width", Vector2(300, 50))), 30.0, 0.001
	)


func test_grid_and_maze_snapping() -> void:
	assert_eq(Snapping.to_grid(Vector2(14, 26), 10.0), Vector2(10, 30))
	assert_eq(Snapping.to_grid(Vector2(14, 26), 0.0), Vector2(14, 26), "no grid, no snap")
	var level := TestEditorActions.maze()
	assert_eq(Snapping.to_maze_corner(level, Vector2(50, 20)), Vector2(35, 35 * 1))
	assert_eq(
		Snapping.to_maze_corner(level, Vector2(-40, 900)), Vector2(0, 315), "kept inside the grid"
	)
	assert_eq(Snapping.to_maze_cell_center(level, Vector2(50, 20)), Vector2(52.5, 17.5))
	assert_eq(Snapping.straighten(Vector2(0, 0), Vector2(70, 10)), Vector2(70, 0))
