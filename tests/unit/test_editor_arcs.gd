extends GutTest
## Pin arcs: selected pins on an arc are recognised (centre, radius, angles, count), shown in
## the Selection panel with a centre mark, and reshaped from its fields in one undo step.

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const PinArc := preload("res://addons/board_editor/core/pin_arc.gd")
const PropertyPanel := preload("res://addons/board_editor/ui/property_panel.gd")
const NewBoard := preload("res://addons/board_editor/core/new_board.gd")
const PatternAction := preload("res://addons/board_editor/actions/pattern_action.gd")
const AddItemsAction := preload("res://addons/board_editor/actions/add_items_action.gd")
const EditArcAction := preload("res://addons/board_editor/actions/edit_arc_action.gd")
const BoardOverlay := preload("res://addons/board_editor/ui/board_overlay.gd")
const SelectTool := preload("res://addons/board_editor/tools/select_tool.gd")


# A board with two loose pins and then a 7-pin arc of radius 100 round (350, 300), from
# -150° to -30°, selected.
func _arc_session() -> BoardEditSession:
	var session := BoardEditSession.new(NewBoard.make(BoardLevel.Kind.PACHINKO))
	var data := BoardItems.empty_set()
	data["pins"] = PackedVector2Array([Vector2(100, 500), Vector2(600, 500)])
	var arc := PinPatterns.arc(Vector2(350, 300), 100.0, -150.0, -30.0, 7)
	data["pins"].append_array(arc)
	var add := AddItemsAction.new(session.level, data, "Add")
	session.commit(add)
	session.select(add.added.slice(2))
	return session


func test_an_arc_pattern_is_recognised_with_its_centre_and_angles() -> void:
	var session := BoardEditSession.new(NewBoard.make(BoardLevel.Kind.PACHINKO))
	var settings := {"kind": "arc", "count": 9, "spacing": 30.0, "radius": 150.0}
	var stamp := PatternAction.new(session.level, settings, Vector2(350, 350))
	session.commit(stamp)
	session.select(stamp.added)
	var arc := session.selected_arc()
	assert_false(arc.is_empty(), "nine pins of an arc pattern are an arc")
	if arc.is_empty():
		return
	assert_almost_eq(PinArc.center_of(arc), Vector2(350, 350), Vector2.ONE * 0.01)
	assert_almost_eq(float(arc["radius"]), 150.0, 0.01)
	assert_eq(int(arc["count"]), 9)
	var span: float = arc["end_deg"] - arc["start_deg"]
	assert_almost_eq((float(arc["start_deg"]) + float(arc["end_deg"])) * 0.5, -90.0, 0.01)
	assert_gt(span, 0.0)


func test_rows_loose_pins_and_pocket_rims_are_not_arcs() -> void:
	var row := PinPatterns.row(Vector2(100, 100), Vector2(300, 100), 5)
	assert_true(PinArc.fit(row).is_empty(), "a straight row")
	var uneven := PinPatterns.arc(Vector2(300, 300), 80.0, 0.0, 90.0, 5)
	uneven[2] = Vector2(300, 300) + Vector2.from_angle(deg_to_rad(30.0)) * 80.0
	assert_true(PinArc.fit(uneven).is_empty(), "on a circle but not evenly spaced")
	var session := _arc_session()
	var mixed := session.selection.duplicate()
	mixed.append(BoardItems.make(BoardItems.Kind.PIN, 0))
	session.select(mixed)
	assert_true(session.selected_arc().is_empty(), "an arc plus a loose pin")


func test_a_whole_circle_comes_back_as_a_circle() -> void:
	var ring := PinPatterns.circle(Vector2(200, 200), 60.0, 12, -90.0)
	var arc := PinArc.fit(ring)
	assert_false(arc.is_empty())
	if arc.is_empty():
		return
	assert_almost_eq(float(arc["end_deg"]) - float(arc["start_deg"]), 360.0, 0.01)
	var again := PinArc.points_of(arc)
	assert_eq(again.size(), 12)
	for point in again:
		assert_almost_eq(point.distance_to(Vector2(200, 200)), 60.0, 0.01)


func test_the_panel_shows_the_arc_and_each_field_is_one_undo_step() -> void:
	var session := _arc_session()
	var level := session.level
	var before := level.pins.duplicate()
	var ids_before := level.pin_ids.duplicate()
	var panel: PropertyPanel = add_child_autofree(PropertyPanel.new())
	panel.bind(session)
	panel.refresh()
	assert_true(panel.field("arc_radius").is_visible_in_tree(), "the arc fields show")
	assert_almost_eq(panel.field("arc_radius").value, 100.0, 0.01)
	assert_almost_eq(panel.field("arc_start_deg").value, -150.0, 0.01)
	assert_almost_eq(panel.field("arc_end_deg").value, -30.0, 0.01)
	assert_eq(panel.field("arc_count").value, 7.0)
	panel.field("arc_radius").value = 140.0
	var arc := session.selected_arc()
	assert_false(arc.is_empty(), "the reshaped arc is still selected")
	assert_almost_eq(float(arc.get("radius", 0.0)), 140.0, 0.01)
	assert_almost_eq(float(arc.get("start_deg", 0.0)), -150.0, 0.01, "the angles stay")
	assert_eq(level.pin_ids, ids_before, "same count: every pin keeps its id")
	panel.field("arc_end_deg").value = 30.0
	panel.field("arc_count").value = 10
	assert_eq(level.pins.size(), 12, "three pins added")
	arc = session.selected_arc()
	assert_eq(int(arc.get("count", 0)), 10)
	assert_almost_eq(float(arc.get("end_deg", 0.0)), 30.0, 0.01)
	assert_eq(level.pins[0], Vector2(100, 500), "the loose pins are untouched")
	panel.field("arc_count").value = 4
	assert_eq(level.pins.size(), 6, "six pins go")
	session.history.undo()
	assert_eq(level.pins.size(), 12, "one undo brings back the ten-pin arc")
	session.history.undo()
	session.history.undo()
	session.history.undo()
	assert_eq(level.pins, before, "four steps back: the arc as placed")


func test_moving_the_centre_moves_the_whole_arc() -> void:
	var session := _arc_session()
	var pins: PackedInt32Array = session.selected_arc()["pins"]
	var shape := session.selected_arc().duplicate()
	shape["center_x"] = 380.0
	var start := session.level.pins[pins[0]]
	session.commit(EditArcAction.new(session.level, pins, shape))
	assert_almost_eq(session.level.pins[pins[0]], start + Vector2(30, 0), Vector2.ONE * 0.001)


func test_the_overlay_draws_a_centre_mark_for_a_selected_arc() -> void:
	var session := _arc_session()
	var canvas: Control = add_child_autofree(Control.new())
	var tool := SelectTool.new(session)
	canvas.draw.connect(
		func() -> void: BoardOverlay.draw(canvas, Transform2D.IDENTITY, session, tool, [], -1)
	)
	canvas.queue_redraw()
	await wait_process_frames(2)
	assert_false(session.selected_arc().is_empty())
	pass_test("drew without errors")
