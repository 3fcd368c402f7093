extends GutTest
## Arcs by three points: two ends and a bulge point give the centre, radius and angles (the
## arc starts at the first end and passes the bulge); points in a line are refused with a
## message; the select tool's arc handles reshape a selected arc in one History step, and the
## pattern tool places an arc by its ends and bulge.

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const PinArc := preload("res://addons/board_editor/core/pin_arc.gd")
const ThreePointArc := preload("res://addons/board_editor/core/three_point_arc.gd")
const NewBoard := preload("res://addons/board_editor/core/new_board.gd")
const AddItemsAction := preload("res://addons/board_editor/actions/add_items_action.gd")
const SelectTool := preload("res://addons/board_editor/tools/select_tool.gd")
const PatternTool := preload("res://addons/board_editor/tools/pattern_tool.gd")
const ArcHandleDrag := preload("res://addons/board_editor/tools/arc_handle_drag.gd")

const CENTRE := Vector2(350, 300)


func _on_circle(degrees: float, radius := 100.0) -> Vector2:
	return CENTRE + Vector2.from_angle(deg_to_rad(degrees)) * radius


func _check_arc(arc: Dictionary, start: float, end: float) -> void:
	assert_false(arc.has("error"), str(arc))
	assert_almost_eq(PinArc.center_of(arc), CENTRE, Vector2.ONE * 0.001)
	assert_almost_eq(float(arc.get("radius", 0.0)), 100.0, 0.001)
	assert_almost_eq(float(arc.get("start_deg", 0.0)), start, 0.001)
	assert_almost_eq(float(arc.get("end_deg", 0.0)), end, 0.001)


func test_three_points_give_the_centre_radius_and_angles() -> void:
	var a := _on_circle(-150.0)
	var b := _on_circle(-30.0)
	_check_arc(ThreePointArc.through(a, _on_circle(-90.0), b, 7), -150.0, -30.0)
	# From the other end: the same arc, run the other way.
	_check_arc(ThreePointArc.through(b, _on_circle(-90.0), a, 7), -30.0, -150.0)
	# Bulging down instead: the long way round, through 90°.
	var long := ThreePointArc.through(a, _on_circle(90.0), b, 7)
	_check_arc(long, -150.0, -390.0)
	var points := PinArc.points_of(long)
	assert_almost_eq(points[3], _on_circle(90.0), Vector2.ONE * 0.001, "the middle pin bulges")
	assert_almost_eq(points[0], a, Vector2.ONE * 0.001, "the first pin on the first end")
	assert_almost_eq(points[6], b, Vector2.ONE * 0.001, "the last pin on the other end")


func test_the_handles_are_the_ends_and_the_middle() -> void:
	var arc := ThreePointArc.through(_on_circle(-150.0), _on_circle(-120.0), _on_circle(-30.0), 5)
	var handles := ThreePointArc.handles(arc)
	assert_almost_eq(handles[0], _on_circle(-150.0), Vector2.ONE * 0.001)
	assert_almost_eq(handles[1], _on_circle(-90.0), Vector2.ONE * 0.001, "the arc's middle")
	assert_almost_eq(handles[2], _on_circle(-30.0), Vector2.ONE * 0.001)


func test_points_in_a_line_are_refused_with_a_clear_message() -> void:
	var line := ThreePointArc.through(Vector2(100, 100), Vector2(200, 100.2), Vector2(300, 100), 5)
	assert_eq(
		line.get("error"),
		"The arc's ends and bulge point are in a line: move the bulge point off the line to bend it."
	)
	var same := ThreePointArc.through(Vector2(100, 100), Vector2(150, 50), Vector2(100, 100), 5)
	assert_eq(same.get("error"), "The arc's two ends are at the same place: drag one end away.")
	var on_end := ThreePointArc.through(Vector2(100, 100), Vector2(100, 100), Vector2(300, 90), 5)
	assert_true(on_end.has("error"), "a bulge on an end bends nothing")


# A pachinko board with a 7-pin arc round CENTRE from -150° to -30°, selected.
func _arc_session() -> BoardEditSession:
	var session := BoardEditSession.new(NewBoard.make(BoardLevel.Kind.PACHINKO))
	var data := BoardItems.empty_set()
	data["pins"] = PinPatterns.arc(CENTRE, 100.0, -150.0, -30.0, 7)
	var add := AddItemsAction.new(session.level, data, "Add")
	session.commit(add)
	session.select(add.added)
	return session


func _mouse(pressed: bool) -> InputEventMouseButton:
	var event := InputEventMouseButton.new()
	event.button_index = MOUSE_BUTTON_LEFT
	event.pressed = pressed
	return event


func test_dragging_the_bulge_reshapes_the_arc_in_one_history_step() -> void:
	var session := _arc_session()
	var level := session.level
	var before := level.pins.duplicate()
	var ids := level.pin_ids.duplicate()
	var steps := session.history.names().size()
	var tool := SelectTool.new(session)
	tool.pixel = 1.0
	var handles := ArcHandleDrag.handle_points(session, 1.0)
	assert_eq(handles.size(), 3, "two ends and a bulge")
	var grab := handles[1]
	assert_almost_eq(
		grab, _on_circle(-90.0, 100.0 + ArcHandleDrag.BULGE_OUTSIDE), Vector2.ONE * 0.01
	)
	tool.press(grab, _mouse(true))
	for k in range(1, 11):
		tool.motion(grab + Vector2(0, -3.0 * k), InputEventMouseMotion.new())  # pull it up 30 px
	tool.release(grab + Vector2(0, -30), _mouse(false))
	assert_eq(session.history.names().size(), steps + 1, "one History step")
	assert_eq(session.history.names()[-1], "Edit pin arc")
	assert_eq(level.pin_ids, ids, "every pin keeps its id")
	assert_almost_eq(level.pins[0], before[0], Vector2.ONE * 0.01, "the ends stay")
	assert_almost_eq(level.pins[6], before[6], Vector2.ONE * 0.01)
	assert_almost_eq(
		level.pins[3], _on_circle(-90.0) + Vector2(0, -30), Vector2.ONE * 0.01, "bulged"
	)
	session.history.undo()
	assert_eq(level.pins, before, "one undo puts the arc back")


func test_dragging_an_end_onto_the_line_holds_the_arc_and_says_why() -> void:
	var session := _arc_session()
	var level := session.level
	var tool := SelectTool.new(session)
	tool.pixel = 1.0
	var first := ArcHandleDrag.handle_points(session, 1.0)[0]
	tool.press(first, _mouse(true))
	tool.motion(first + Vector2(-20, 0), InputEventMouseMotion.new())
	var good := level.pins.duplicate()
	# The first end dragged onto the line through the bulge and the other end.
	var middle := _on_circle(-90.0)
	var other := _on_circle(-30.0)
	var on_line := middle + (middle - other)
	tool.motion(on_line, InputEventMouseMotion.new())
	assert_string_contains(tool._arc_drag.problem, "in a line")
	assert_eq(level.pins, good, "the last good shape stays")
	tool.cancel()
	assert_almost_eq(level.pins[0], _on_circle(-150.0), Vector2.ONE * 0.01, "cancel puts it back")


func test_the_pattern_tool_places_an_arc_by_its_ends_and_bulge() -> void:
	var session := BoardEditSession.new(NewBoard.make(BoardLevel.Kind.PACHINKO))
	session.snap_enabled = false
	session.pattern = {"kind": "arc", "count": 5, "spacing": 30.0, "radius": 150.0}
	var tool := PatternTool.new(session)
	tool.pixel = 1.0
	var steps := session.history.names().size()
	tool.press(_on_circle(180.0), _mouse(true))
	tool.release(_on_circle(0.0), _mouse(false))  # dragged from one end to the other
	tool.press(_on_circle(-90.0), _mouse(true))  # the bulge: up
	assert_eq(session.history.names().size(), steps + 1, "one History step")
	assert_eq(session.history.names()[-1], "Add a 5-pin arc")
	var pins := session.level.pins
	assert_eq(pins.size(), 5)
	assert_almost_eq(pins[0], _on_circle(180.0), Vector2.ONE * 0.01, "on the first end")
	assert_almost_eq(pins[2], _on_circle(-90.0), Vector2.ONE * 0.01, "through the bulge")
	assert_almost_eq(pins[4], _on_circle(0.0), Vector2.ONE * 0.01, "on the other end")
	# A bulge on the line between the ends places nothing.
	tool.press(Vector2(100, 600), _mouse(true))
	tool.press(Vector2(300, 600), _mouse(true))
	tool.press(Vector2(200, 600), _mouse(true))
	assert_eq(session.history.names().size(), steps + 1, "nothing placed in a line")
	assert_true(tool.arc_for(Vector2(200, 600)).has("error"))
