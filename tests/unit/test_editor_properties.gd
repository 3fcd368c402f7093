extends GutTest
## The Selection panel: exact numbers for one selected item, each typed value one undo step
## (a pin's x / y, a pocket's payout and size, a wall's end, the goal's radius).

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const ItemProperties := preload("res://addons/board_editor/core/item_properties.gd")
const PropertyPanel := preload("res://addons/board_editor/ui/property_panel.gd")
const TestEditorTools := preload("res://tests/unit/test_editor_tools.gd")
const NewBoard := preload("res://addons/board_editor/core/new_board.gd")
const AddItemsAction := preload("res://addons/board_editor/actions/add_items_action.gd")


func _pachinko_with_pin_and_pocket() -> BoardEditSession:
	var session := BoardEditSession.new(NewBoard.make(BoardLevel.Kind.PACHINKO))
	var data := BoardItems.empty_set()
	data["pins"] = PackedVector2Array([Vector2(300, 200)])
	data["pockets"] = [PocketSpec.create(Vector2(350, 400), 32.0, 24.0, 10)]
	session.commit(AddItemsAction.new(session.level, data, "Add"))
	return session


func test_typing_a_pins_exact_position_is_one_undo_step() -> void:
	var session := _pachinko_with_pin_and_pocket()
	var panel: PropertyPanel = add_child_autofree(PropertyPanel.new())
	panel.bind(session)
	session.select([BoardItems.make(BoardItems.Kind.PIN, 0)] as Array[Vector2i])
	panel.refresh()
	assert_eq(panel.field("x").value, 300.0, "the panel shows the pin's x")
	assert_true(panel.field("x").get_parent().visible)
	assert_false(panel.field("payout").get_parent().visible, "no payout row for a pin")
	panel.field("x").value = 312.5
	assert_eq(session.level.pins[0], Vector2(312.5, 200))
	panel.field("y").value = 205.0
	assert_eq(session.level.pins[0], Vector2(312.5, 205))
	session.history.undo()
	assert_eq(session.level.pins[0], Vector2(312.5, 200), "one undo takes back only the y")
	session.history.undo()
	assert_eq(session.level.pins[0], Vector2(300, 200))


func test_a_pockets_payout_and_width_change_in_the_panel() -> void:
	var session := _pachinko_with_pin_and_pocket()
	var panel: PropertyPanel = add_child_autofree(PropertyPanel.new())
	panel.bind(session)
	var pocket := BoardItems.make(BoardItems.Kind.POCKET, 0)
	session.select([pocket] as Array[Vector2i])
	panel.refresh()
	assert_eq(panel.field("payout").value, 10.0)
	panel.field("payout").value = 25
	assert_eq(session.level.pockets[0].payout, 25)
	var rim_before := _rim_span(session.level)
	panel.field("width").value = 48
	assert_eq(session.level.pockets[0].width, 48.0)
	assert_gt(_rim_span(session.level), rim_before, "a wider rim, re-stamped")
	session.history.undo()
	assert_eq(session.level.pockets[0].width, 32.0)
	assert_eq(session.level.pockets[0].payout, 25, "the payout change is its own step")
	panel.field("x").value = 330
	assert_eq(session.level.pockets[0].position, Vector2(330, 400), "the mouth moves")


func test_wall_ends_and_the_goal() -> void:
	var session := BoardEditSession.new(NewBoard.make(BoardLevel.Kind.MAZE))
	var level := session.level
	var wall := BoardItems.make(BoardItems.Kind.WALL, 0)
	var values := ItemProperties.values_of(level, wall)
	assert_eq(values.keys(), ["ax", "ay", "bx", "by"])
	session.commit(ItemProperties.action_for(level, wall, "bx", 140.0))
	assert_eq(level.walls[1].x, 140.0, "end B moved")
	assert_eq(level.walls[0], Vector2.ZERO, "end A stays")
	var goal := BoardItems.make(BoardItems.Kind.GOAL, 0)
	session.commit(ItemProperties.action_for(level, goal, "radius", 40.0))
	assert_eq(level.goal_radius, 40.0)
	assert_null(ItemProperties.action_for(level, goal, "radius", 40.0), "no step for no change")
	session.history.undo()
	assert_eq(level.goal_radius, 32.5)


func _rim_span(level: BoardLevel) -> float:
	var xs: Array[float] = []
	for pin in BoardItems.pocket_pins(level, 0):
		xs.append(level.pins[pin].x)
	return xs.max() - xs.min()


func test_fields_keep_the_boards_precision_and_whole_numbers_stay_whole() -> void:
	var session := _pachinko_with_pin_and_pocket()
	var pins := session.level.pins
	pins[0] = Vector2(373.33, 201.27)
	session.level.pins = pins
	var panel: PropertyPanel = add_child_autofree(PropertyPanel.new())
	panel.bind(session)
	session.select([BoardItems.make(BoardItems.Kind.PIN, 0)] as Array[Vector2i])
	panel.refresh()
	assert_almost_eq(panel.field("x").value, 373.33, 1e-4, "not rounded to 373.5")
	assert_almost_eq(panel.field("y").value, 201.27, 1e-4)
	assert_eq(session.level.pins[0], Vector2(373.33, 201.27), "showing it moves nothing")
	panel.field("x").value = 380.25
	assert_eq(session.level.pins[0], Vector2(380.25, 201.27), "a typed 380.25 is kept")
	assert_eq(panel.field("x").custom_arrow_step, 0.5, "the arrows still step by half a pixel")
	session.select([BoardItems.make(BoardItems.Kind.POCKET, 0)] as Array[Vector2i])
	panel.refresh()
	panel.field("payout").value = 7.4
	assert_eq(session.level.pockets[0].payout, 7, "a payout stays a whole number")
