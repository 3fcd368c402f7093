extends GutTest
## Editing several selected items in the Selection panel: the fields they all have, mixed
## values shown as mixed, a typed value set on every one in one undo step (redo too), and
## in mirror mode their twins following.

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const ItemProperties := preload("res://addons/board_editor/core/item_properties.gd")
const PropertyPanel := preload("res://addons/board_editor/ui/property_panel.gd")
const NewBoard := preload("res://addons/board_editor/core/new_board.gd")
const AddItemsAction := preload("res://addons/board_editor/actions/add_items_action.gd")


# A pachinko board with three pockets (payouts 10, 10, 4; the first two mirror twins) and two
# field pins.
func _session() -> BoardEditSession:
	var session := BoardEditSession.new(NewBoard.make(BoardLevel.Kind.PACHINKO))
	var axis := session.level.ring_center.x  # the mirror axis
	var data := BoardItems.empty_set()
	data["pins"] = PackedVector2Array([Vector2(300, 200), Vector2(320, 230)])
	data["pockets"] = [
		PocketSpec.create(Vector2(axis - 80, 400), 32.0, 24.0, 10),
		PocketSpec.create(Vector2(axis + 80, 400), 32.0, 24.0, 10),
		PocketSpec.create(Vector2(axis, 470), 28.0, 24.0, 4),
	]
	session.commit(AddItemsAction.new(session.level, data, "Add"))
	return session


func _panel(session: BoardEditSession) -> PropertyPanel:
	var panel: PropertyPanel = add_child_autofree(PropertyPanel.new())
	panel.bind(session)
	return panel


func _pockets(indices: Array[int]) -> Array[Vector2i]:
	var items: Array[Vector2i] = []
	for i in indices:
		items.append(BoardItems.make(BoardItems.Kind.POCKET, i))
	return items


func test_shared_fields_with_mixed_values_are_shown_as_mixed() -> void:
	var session := _session()
	var panel := _panel(session)
	session.select(_pockets([0, 2]))
	panel.refresh()
	assert_true(panel.field("payout").get_parent().visible, "both have a payout")
	assert_true(panel.is_mixed("payout"), "10 and 4")
	assert_eq(panel.field("payout").get_line_edit().text, "", "an empty box...")
	assert_eq(panel.field("payout").get_line_edit().placeholder_text, "mixed", "...says mixed")
	assert_false(panel.is_mixed("depth"), "both 24 deep")
	assert_eq(panel.field("depth").value, 24.0)
	assert_false(panel.field("radius").get_parent().visible, "no pocket has a radius")
	session.select(
		[BoardItems.make(BoardItems.Kind.PIN, 0), BoardItems.make(BoardItems.Kind.POCKET, 2)]
	)
	panel.refresh()
	assert_false(panel.field("payout").get_parent().visible, "a pin has no payout")
	assert_true(panel.field("x").get_parent().visible, "but both have an x")


func test_typing_sets_every_selected_item_in_one_undo_step() -> void:
	var session := _session()
	var panel := _panel(session)
	session.select(_pockets([0, 1, 2]))
	panel.refresh()
	var steps := session.history.names().size()
	panel.field("payout").value = 7
	var level := session.level
	assert_eq(
		[level.pockets[0].payout, level.pockets[1].payout, level.pockets[2].payout], [7, 7, 7]
	)
	assert_false(panel.is_mixed("payout"), "no longer mixed")
	assert_eq(session.history.names().size(), steps + 1, "one History step")
	assert_eq(session.history.names()[-1], "Set payout of 3 items")
	session.history.undo()
	assert_eq(
		[level.pockets[0].payout, level.pockets[1].payout, level.pockets[2].payout], [10, 10, 4]
	)
	session.history.redo()
	assert_eq(level.pockets[2].payout, 7, "redo sets them all again")


func test_a_size_change_restamps_each_pocket_and_keeps_the_pins_straight() -> void:
	var session := _session()
	var panel := _panel(session)
	var pin := BoardItems.make(BoardItems.Kind.PIN, 1)
	var items := _pockets([0, 2])
	items.append(pin)
	session.select(items)
	panel.refresh()
	panel.field("y").value = 260.0
	var level := session.level
	assert_eq(level.pockets[0].position.y, 260.0)
	assert_eq(level.pockets[2].position.y, 260.0)
	var field_pins := PackedVector2Array()
	for i in level.pins.size():
		if level.pin_pocket[i] < 0:
			field_pins.append(level.pins[i])
	assert_eq(field_pins, PackedVector2Array([Vector2(300, 200), Vector2(320, 260)]))
	session.history.undo()
	assert_eq(level.pockets[0].position.y, 400.0)
	assert_eq(level.pockets[2].position.y, 470.0)


func test_enter_in_a_mixed_field_sets_all_even_to_the_value_the_box_held() -> void:
	var session := _session()
	var panel := _panel(session)
	session.select(_pockets([2, 0]))
	panel.refresh()
	var held := panel.field("payout").value
	panel.field("payout").get_line_edit().text_submitted.emit(str(int(held)))
	assert_eq(session.level.pockets[0].payout, int(held))
	assert_eq(session.level.pockets[2].payout, int(held))


func test_mirror_twins_follow_a_field_typed_on_several_items() -> void:
	var session := _session()
	session.set_mirror(true)
	var panel := _panel(session)
	session.select(_pockets([0, 2]))
	panel.refresh()
	panel.field("width").value = 36.0
	var level := session.level
	assert_eq(level.pockets[1].width, 36.0, "the unselected twin takes the same width")
	assert_eq(level.pockets[0].width, 36.0)
	assert_eq(level.pockets[2].width, 36.0)
	assert_eq(session.history.names()[-1], "Set width of 3 items")
	var axis := session.mirror_axis()
	session.select(_pockets([0, 1]))
	panel.refresh()
	panel.field("x").value = axis - 100.0
	assert_eq(level.pockets[0].position.x, axis - 100.0)
	assert_eq(level.pockets[1].position.x, axis + 100.0, "a selected twin mirrors its partner")
	session.history.undo()
	assert_eq(level.pockets[1].position.x, axis + 80.0)


func test_nothing_changes_nothing_is_recorded() -> void:
	var session := _session()
	var steps := session.history.names().size()
	var same := ItemProperties.action_for_all(session.level, _pockets([0, 1]), "payout", 10.0)
	assert_null(same, "both already pay 10")
	assert_eq(session.history.names().size(), steps)
