extends GutTest
## Stable item ids: they survive deleting a neighbour, come back with an undo, are written
## in the board file and read back, and the validator's messages name items by them.

const Session := preload("res://addons/board_editor/board_edit_session.gd")
const Items := preload("res://addons/board_editor/core/board_items.gd")
const ItemNames := preload("res://addons/board_editor/core/item_names.gd")
const Commands := preload("res://addons/board_editor/core/edit_commands.gd")
const Tools := preload("res://tests/unit/test_editor_tools.gd")
const NewBoard := preload("res://addons/board_editor/core/new_board.gd")
const AddItemsAction := preload("res://addons/board_editor/actions/add_items_action.gd")
const Writer := preload("res://scripts/loading/board_text_writer.gd")
const Reader := preload("res://scripts/loading/board_text_reader.gd")


func _pins(count: int) -> BoardLevel:
	var helper := Tools.new()
	var level := helper.pins(count)
	helper.free()
	return level


func test_ids_survive_deleting_a_neighbour_and_undo_brings_it_back() -> void:
	var session := Session.new(_pins(5))
	var level := session.level
	assert_eq(ItemIds.of(level, "pins", 3), 4, "a board without ids numbers items in order")
	session.select([Items.make(Items.Kind.PIN, 1)] as Array[Vector2i])
	Commands.delete_selection(session)
	assert_eq(level.pins.size(), 4)
	assert_eq(ItemIds.of(level, "pins", 2), 4, "the pin that was 4th is still pin 4")
	assert_eq(ItemNames.name_of(level, Items.make(Items.Kind.PIN, 2)), "Pin 4")
	session.history.undo()
	assert_eq(ItemIds.of(level, "pins", 3), 4)
	assert_eq(ItemIds.of(level, "pins", 1), 2, "undo brings pin 2 back as pin 2")


func test_new_items_get_fresh_ids_and_the_file_keeps_them() -> void:
	var session := Session.new(NewBoard.make(BoardLevel.Kind.PACHINKO))
	var level := session.level
	var data := Items.empty_set()
	data["pins"] = PackedVector2Array([Vector2(200, 200), Vector2(250, 200), Vector2(300, 200)])
	session.commit(AddItemsAction.new(level, data, "Add pins"))
	session.select([Items.make(Items.Kind.PIN, 0)] as Array[Vector2i])
	Commands.delete_selection(session)
	data["pins"] = PackedVector2Array([Vector2(300, 300)])
	session.commit(AddItemsAction.new(level, data, "Add pin"))
	var ids := [ItemIds.of(level, "pins", 0), ItemIds.of(level, "pins", 1)]
	assert_eq(ids, [2, 3], "the survivors keep 2 and 3")
	assert_eq(ItemIds.of(level, "pins", 2), 4, "the new pin gets a fresh id")
	var text := Writer.write(level)
	assert_string_contains(text, '{"pin": {"id": 4, "x": 300, "y": 300}}')
	var read: Dictionary = Reader.read(text)
	var back: BoardLevel = read.get("level")
	assert_not_null(back, str(read.get("error", "")))
	if back != null:
		assert_eq(back.pin_ids, PackedInt32Array([2, 3, 4]), "ids read back from the file")


func test_problem_messages_name_items_by_stable_id() -> void:
	var session := Session.new(_pins(4))
	var level := session.level
	var pins := level.pins
	pins[3] = pins[2]  # pins 3 and 4 overlap
	level.pins = pins
	assert_true(_has_message(level, "Pins 3 and 4 overlap."))
	session.select([Items.make(Items.Kind.PIN, 0)] as Array[Vector2i])
	Commands.delete_selection(session)
	assert_true(_has_message(level, "Pins 3 and 4 overlap."), "still 3 and 4 after a delete")


func test_repeated_ids_in_a_file_are_renumbered() -> void:
	var level := _pins(3)
	level.pin_ids = PackedInt32Array([7, 7, 0])
	ItemIds.fill(level)
	assert_eq(level.pin_ids, PackedInt32Array([7, 8, 9]))


func _has_message(level: BoardLevel, text: String) -> bool:
	for issue in BoardValidator.validate(level):
		if issue.message == text:
			return true
	return false
