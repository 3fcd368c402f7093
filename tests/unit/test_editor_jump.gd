extends GutTest
## Jump-to-problem: a problem that covers several items (two pins, a start and the goal it
## cannot reach, a ring poking out) carries its whole area, and the jump's zoom frames that
## area, zooming out when it is larger than the view and in when the view is far out.

const ViewFocus := preload("res://addons/board_editor/ui/view_focus.gd")
const NewBoard := preload("res://addons/board_editor/core/new_board.gd")

const VIEW := Vector2(1000, 600)


func test_a_large_area_zooms_the_view_out_until_it_fits() -> void:
	var zoom := ViewFocus.zoom_for(4.0, Vector2(700, 700), VIEW)
	assert_almost_eq(zoom, 600.0 * ViewFocus.FILL / 700.0, 0.001, "out to fit the height")
	assert_lt(zoom * 700.0, VIEW.y, "the whole area is on screen")


func test_a_balance_table_line_never_zooms_in() -> void:
	assert_eq(ViewFocus.zoom_for(1.0, Vector2(30, 30), VIEW, false), 1.0, "the zoom stays 100 %")
	var out := ViewFocus.zoom_for(4.0, Vector2(700, 700), VIEW, false)
	assert_lt(out, 4.0, "but out, when the item does not fit")


func test_a_small_problem_zooms_in_from_far_out_and_keeps_a_close_view() -> void:
	assert_eq(ViewFocus.zoom_for(0.5, Vector2(4, 4), VIEW), ViewFocus.CLOSE_ZOOM)
	assert_eq(ViewFocus.zoom_for(3.0, Vector2(4, 4), VIEW), 3.0, "already close: kept")
	assert_eq(ViewFocus.zoom_for(0.5, Vector2.ZERO, VIEW), ViewFocus.CLOSE_ZOOM, "a point")
	var mid := ViewFocus.zoom_for(0.5, Vector2(400, 100), VIEW)
	assert_almost_eq(mid, 1000.0 * ViewFocus.FILL / 400.0, 0.001, "in, but not past the fit")


func test_a_start_that_cannot_reach_the_goal_covers_start_and_goal() -> void:
	var level := NewBoard.make(BoardLevel.Kind.MAZE)
	var start := level.ball_starts[0]
	# Box the first start in with four walls round its cell.
	var half := level.path_width * 0.5 + level.wall_width * 0.5
	var box := PackedVector2Array()
	for corner in [Vector2(-1, -1), Vector2(1, -1), Vector2(1, 1), Vector2(-1, 1)]:
		box.append(start + corner * half)
	var walls := level.walls.duplicate()
	for i in 4:
		walls.append(box[i])
		walls.append(box[(i + 1) % 4])
	level.walls = walls
	var issue := _issue(level, "start_cannot_reach_goal")
	assert_not_null(issue, "the boxed-in start is reported")
	if issue == null:
		return
	var extent := issue.extent()
	assert_true(extent.has_point(start), "the frame holds the start")
	assert_true(extent.grow(0.01).has_point(level.goal_center), "and the goal")
	assert_gt(extent.size.length(), 100.0)


func test_two_overlapping_pins_and_a_ring_off_the_board_cover_their_items() -> void:
	var level := NewBoard.make(BoardLevel.Kind.PACHINKO)
	level.pins = PackedVector2Array([Vector2(300, 300), Vector2(301, 300)])
	level.pin_pocket = PackedInt32Array([-1, -1])
	level.pin_special = PackedByteArray([0, 0])
	var pair := _issue(level, "pin_overlap")
	assert_not_null(pair)
	if pair != null:
		assert_true(pair.extent().grow(0.01).has_point(Vector2(300 - level.pin_radius, 300)))
		assert_true(pair.extent().grow(0.01).has_point(Vector2(301 + level.pin_radius, 300)))
	level.ring_center = Vector2(250, 350)
	var ring := _issue(level, "ring_outside_board")
	assert_not_null(ring)
	if ring != null:
		assert_almost_eq(ring.extent().size, Vector2.ONE * level.ring_radius * 2.0, Vector2.ONE)


func test_a_problem_at_one_point_frames_that_point() -> void:
	var issue := BoardIssue.new(BoardIssue.Severity.WARNING, "x", Vector2(10, 20), "x")
	assert_eq(issue.extent(), Rect2(10, 20, 0, 0))


func _issue(level: BoardLevel, code: String) -> BoardIssue:
	for issue in BoardValidator.validate(level):
		if issue.kind == code:
			return issue
	return null
