extends GutTest
## Stable item ids: they survive deleting a neighbour, come back with an undo, are written
## in the board file and read back, and the validator's messages name items by them.

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const ItemNames := preload("res://addons/board_editor/core/item_names.gd")
const EditCommands := preload("res://addons/board_editor/core/edit_commands.gd")
const TestEditorTools := preload("res://tests/unit/test_editor_tools.gd")
const NewBoard := preload("res://addons/board_editor/core/new_board.gd")
const AddItemsAction := preload("res://addons/board_editor/actions/add_items_action.gd")
const DeleteItemsAction := preload("res://addons/board_editor/actions/delete_items_action.gd")


func _pins(count: int) -> BoardLevel:
	var helper := TestEditorTools.new()
	var level := helper.pins(count)
	helper.free()
	return level


# A board the reader accepts, with `count` pins in a row.
func _saveable_pins(count: int) -> BoardLevel:
	var level := NewBoard.make(BoardLevel.Kind.PACHINKO)
	var pins := PackedVector2Array()
	for i in count:
		pins.append(Vector2(200 + i * 20, 200))
	level.pins = pins
	level.pin_pocket.resize(count)
	level.pin_pocket.fill(-1)
	level.pin_special.resize(count)
	return level


func test_ids_survive_deleting_a_neighbour_and_undo_brings_it_back() -> void:
	var session := BoardEditSession.new(_pins(5))
	var level := session.level
	assert_eq(ItemIds.of(level, "pins", 3), 4, "a board without ids numbers items in order")
	session.select([BoardItems.make(BoardItems.Kind.PIN, 1)] as Array[Vector2i])
	EditCommands.delete_selection(session)
	assert_eq(level.pins.size(), 4)
	assert_eq(ItemIds.of(level, "pins", 2), 4, "the pin that was 4th is still pin 4")
	assert_eq(ItemNames.name_of(level, BoardItems.make(BoardItems.Kind.PIN, 2)), "Pin 4")
	session.history.undo()
	assert_eq(ItemIds.of(level, "pins", 3), 4)
	assert_eq(ItemIds.of(level, "pins", 1), 2, "undo brings pin 2 back as pin 2")


func test_new_items_get_fresh_ids_and_the_file_keeps_them() -> void:
	var session := BoardEditSession.new(NewBoard.make(BoardLevel.Kind.PACHINKO))
	var level := session.level
	var data := BoardItems.empty_set()
	data["pins"] = PackedVector2Array([Vector2(200, 200), Vector2(250, 200), Vector2(300, 200)])
	session.commit(AddItemsAction.new(level, data, "Add pins"))
	session.select([BoardItems.make(BoardItems.Kind.PIN, 0)] as Array[Vector2i])
	EditCommands.delete_selection(session)
	data["pins"] = PackedVector2Array([Vector2(300, 300)])
	session.commit(AddItemsAction.new(level, data, "Add pin"))
	var ids := [ItemIds.of(level, "pins", 0), ItemIds.of(level, "pins", 1)]
	assert_eq(ids, [2, 3], "the survivors keep 2 and 3")
	assert_eq(ItemIds.of(level, "pins", 2), 4, "the new pin gets a fresh id")
	var text := BoardTextWriter.write(level)
	assert_string_contains(text, '{"pin": {"id": 4, "x": 300, "y": 300}}')
	var read: Dictionary = BoardTextReader.read(text)
	var back: BoardLevel = read.get("level")
	assert_not_null(back, str(read.get("error", "")))
	if back != null:
		assert_eq(back.pin_ids, PackedInt32Array([2, 3, 4]), "ids read back from the file")


func test_problem_messages_name_items_by_stable_id() -> void:
	var session := BoardEditSession.new(_pins(4))
	var level := session.level
	var pins := level.pins
	pins[3] = pins[2]  # pins 3 and 4 overlap
	level.pins = pins
	assert_true(_has_message(level, "Pins 3 and 4 overlap."))
	session.select([BoardItems.make(BoardItems.Kind.PIN, 0)] as Array[Vector2i])
	EditCommands.delete_selection(session)
	assert_true(_has_message(level, "Pins 3 and 4 overlap."), "still 3 and 4 after a delete")


func test_repeated_ids_in_a_file_are_renumbered() -> void:
	var level := _pins(3)
	level.pin_ids = PackedInt32Array([7, 7, 0])
	ItemIds.fill(level)
	assert_eq(level.pin_ids, PackedInt32Array([7, 8, 9]))


func test_deleting_the_highest_item_never_frees_its_id() -> void:
	var session := BoardEditSession.new(_saveable_pins(5))
	var level := session.level
	session.select([BoardItems.make(BoardItems.Kind.PIN, 4)] as Array[Vector2i])
	EditCommands.delete_selection(session)
	assert_string_contains(BoardTextWriter.write(level), '{"next_ids": {"pins": 6}}')
	_add_pin(session, Vector2(300, 300))
	assert_eq(ItemIds.of(level, "pins", 4), 6, "pin 5 was deleted: the new pin is 6, not 5")
	assert_false(BoardTextWriter.write(level).contains("next_ids"), "6 is in use: no line needed")
	session.select([BoardItems.make(BoardItems.Kind.PIN, 4)] as Array[Vector2i])
	EditCommands.delete_selection(session)
	var read: Dictionary = BoardTextReader.read(BoardTextWriter.write(level))
	var back: BoardLevel = read.get("level")
	assert_not_null(back, str(read.get("error", "")))
	if back == null:
		return
	assert_eq(ItemIds.next_id(back, "pins"), 7, "the counter survives a save and a load")
	var reopened := BoardEditSession.new(back)
	_add_pin(reopened, Vector2(320, 300))
	assert_eq(ItemIds.of(back, "pins", 4), 7, "pin 6 is gone too: the next pin is 7")


func test_undo_of_an_add_keeps_the_id_used_and_redo_gives_it_back() -> void:
	var session := BoardEditSession.new(_pins(3))
	var level := session.level
	_add_pin(session, Vector2(300, 300))
	assert_eq(ItemIds.of(level, "pins", 3), 4)
	session.history.undo()
	session.history.redo()
	assert_eq(ItemIds.of(level, "pins", 3), 4, "a redo brings the pin back as pin 4")
	session.history.undo()
	_add_pin(session, Vector2(320, 300))
	assert_eq(ItemIds.of(level, "pins", 3), 5, "id 4 was handed out once: the next add is 5")


func test_a_board_whose_counter_follows_its_ids_writes_no_counter_line() -> void:
	var level := _pins(4)
	ItemIds.fill(level)
	assert_false(BoardTextWriter.write(level).contains("next_ids"))


func test_counters_in_a_file_are_checked() -> void:
	var text := BoardTextWriter.write(_saveable_pins(3))
	var cases := {
		'{"next_ids": [4]}': '"next_ids" must be an object',
		'{"next_ids": {"pegs": 4}}': '"pegs", which is not an item list',
		'{"next_ids": {"walls": 4}}': '"walls", which is not an item list',
		'{"next_ids": {"pins": 0}}': "must be between 1 and",
		'{"next_ids": {"pins": 2.5}}': "must be a whole number",
	}
	for line: String in cases:
		var read: Dictionary = BoardTextReader.read(text + line + "\n")
		assert_false(read.has("level"), line)
		assert_string_contains(str(read.get("error", "")), cases[line])
	var low: BoardLevel = BoardTextReader.read(text + '{"next_ids": {"pins": 2}}\n').get("level")
	assert_not_null(low, "a counter below the ids in use is not an error")
	if low != null:
		assert_eq(ItemIds.next_id(low, "pins"), 4, "it is raised past the largest id")


func _add_pin(session: BoardEditSession, at: Vector2) -> void:
	var data := BoardItems.empty_set()
	data["pins"] = PackedVector2Array([at])
	session.commit(AddItemsAction.new(session.level, data, "Add pin"))


func _has_message(level: BoardLevel, text: String) -> bool:
	for issue in BoardValidator.validate(level):
		if issue.message == text:
			return true
	return false


func test_the_selection_follows_its_items_by_id_when_others_are_renumbered() -> void:
	var session := BoardEditSession.new(_pins(5))
	var level := session.level
	var kept := level.pins[3]
	session.select([BoardItems.make(BoardItems.Kind.PIN, 3)] as Array[Vector2i])
	# A pin before the selected one goes (an undoable delete, as the Erase tool does it).
	var gone: Array[Vector2i] = [BoardItems.make(BoardItems.Kind.PIN, 1)]
	session.commit(DeleteItemsAction.new(level, gone))
	assert_eq(session.selection, [BoardItems.make(BoardItems.Kind.PIN, 2)] as Array[Vector2i])
	assert_eq(level.pins[session.selection[0].y], kept, "still the pin that was selected")
	session.history.undo()
	session.prune_selection()
	assert_eq(
		session.selection, [BoardItems.make(BoardItems.Kind.PIN, 3)] as Array[Vector2i], "undo too"
	)


func test_a_selected_item_that_is_deleted_leaves_the_selection() -> void:
	var session := BoardEditSession.new(_pins(3))
	var level := session.level
	session.select([BoardItems.make(BoardItems.Kind.PIN, 0)] as Array[Vector2i])
	var gone: Array[Vector2i] = [BoardItems.make(BoardItems.Kind.PIN, 0)]
	session.commit(DeleteItemsAction.new(level, gone))
	assert_eq(session.selection, [] as Array[Vector2i], "not the pin that moved into its place")
