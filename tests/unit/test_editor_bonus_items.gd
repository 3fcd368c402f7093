extends GutTest
## Bonus pockets (start pockets, attackers, tulips) as first-class editor items: stable ids
## in the file that are never handed out twice, picked, dragged, box-selected, erased,
## mirrored, aligned and duplicated like pockets (one undo step per gesture), named by id in
## the editor and in the validator's messages, and on their own "Bonus pieces" layer.

## A frozen bonus board (the first Fever layout), so rebalancing the shipped boards never
## moves the pieces these tests pick.
const BONUS_BOARD := "res://tests/fixtures/boards/bonus_layout.board"
const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const BoardInput := preload("res://addons/board_editor/board_input.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const ItemNames := preload("res://addons/board_editor/core/item_names.gd")
const HitTest := preload("res://addons/board_editor/core/hit_test.gd")
const Layers := preload("res://addons/board_editor/core/layers.gd")
const LayersPanel := preload("res://addons/board_editor/ui/layers_panel.gd")
const EditCommands := preload("res://addons/board_editor/core/edit_commands.gd")
const Arrange := preload("res://addons/board_editor/core/arrange.gd")
const ArrangeAction := preload("res://addons/board_editor/actions/arrange_action.gd")
const DeleteItemsAction := preload("res://addons/board_editor/actions/delete_items_action.gd")
const BonusActions := preload("res://addons/board_editor/bonus/bonus_actions.gd")
const PropertyPanel := preload("res://addons/board_editor/ui/property_panel.gd")

# bonus_layout.board: start pocket 1 at (350, 400), attacker 1 at (350, 540), tulips 1 and 2 at
# (215, 330) and (485, 330), mirrored across x = 350.
const TULIP_1 := Vector2(215, 330)
const TULIP_2 := Vector2(485, 330)

var session: BoardEditSession
var input: BoardInput


func _open() -> BoardLevel:
	var level := (load(BONUS_BOARD) as BoardLevel).duplicate_level()
	session = BoardEditSession.new(level)
	input = BoardInput.new(session)
	session.snap_enabled = false
	return level


func _press(at: Vector2, down: bool) -> void:
	var event := InputEventMouseButton.new()
	event.button_index = MOUSE_BUTTON_LEFT
	event.pressed = down
	event.position = at
	input.handle(event, Transform2D.IDENTITY)


func _drag(from: Vector2, to: Vector2) -> void:
	_press(from, true)
	for step in [0.5, 1.0]:
		var event := InputEventMouseMotion.new()
		event.position = from.lerp(to, step)
		event.button_mask = MOUSE_BUTTON_MASK_LEFT
		input.handle(event, Transform2D.IDENTITY)
	_press(to, false)


func _bonus(list: String, id: int) -> Vector2i:
	return BoardItems.make(BoardItems.Kind.BONUS, ItemIds.bonus_index(session.level, list, id))


func _messages(level: BoardLevel) -> String:
	var lines := PackedStringArray()
	for issue in BoardValidator.validate(level):
		lines.append(issue.message)
	return "\n".join(lines)


func test_the_file_keeps_bonus_ids_and_a_deleted_id_is_never_handed_out_again() -> void:
	var level := _open()
	var text := BoardTextWriter.write(level)
	assert_string_contains(text, '{"tulip": {"id": 2, "x": 485, "y": 330')
	assert_string_contains(text, '{"attacker": {"id": 1, "x": 350, "y": 540')
	assert_eq(ItemNames.name_of(level, _bonus("tulips", 2)), "Tulip 2")
	session.commit(DeleteItemsAction.new(level, [_bonus("tulips", 2)] as Array[Vector2i]))
	var spec := BonusPocketSpec.of_role(BonusPocketSpec.Role.TULIP, Vector2(485, 250), 26, 26, 3)
	session.commit(BonusActions.AddBonus.new(level, spec))
	assert_eq(ItemIds.of_bonus(level, level.bonus_pockets.find(spec)), 3, "2 is not reused")
	var saved := BoardTextWriter.write(level)
	assert_string_contains(saved, '{"tulip": {"id": 3, "x": 485, "y": 250')
	var again: BoardLevel = BoardTextReader.read(saved)["level"]
	assert_eq(BoardTextWriter.write(again), saved, "ids read back as written")
	session.history.undo()
	session.history.undo()
	assert_eq(ItemIds.of_bonus(level, 3), 2, "undo brings tulip 2 back under its own id")
	var after_undo := BoardTextWriter.write(level)
	assert_string_contains(after_undo, '{"tulip": {"id": 2, "x": 485, "y": 330')
	assert_string_contains(after_undo, '{"next_ids": {"tulips": 4}}', "3 stays used up")


func test_ids_survive_deleting_a_neighbour_and_the_validator_names_them_by_id() -> void:
	var level := _open()
	session.commit(DeleteItemsAction.new(level, [_bonus("tulips", 1)] as Array[Vector2i]))
	var tulip := _bonus("tulips", 2)
	assert_eq(ItemNames.name_of(level, tulip), "Tulip 2", "the right tulip is still tulip 2")
	level.bonus_pockets[tulip.y].position = Vector2(350, 410)
	assert_string_contains(_messages(level), "Start pocket 1 overlaps Tulip 2.")


func test_select_picks_a_bonus_pocket_and_a_drag_moves_it_in_one_undo_step() -> void:
	var level := _open()
	session.set_tool(BoardEditSession.Tool.SELECT)
	_drag(TULIP_1 + Vector2(0, 4), TULIP_1 + Vector2(20, 14))
	assert_eq(session.selection, [_bonus("tulips", 1)] as Array[Vector2i])
	assert_eq(level.bonus_pockets[2].position, TULIP_1 + Vector2(20, 10))
	assert_eq(session.history.names().size(), 1, "one drag, one step")
	session.history.undo()
	assert_eq(level.bonus_pockets[2].position, TULIP_1)
	session.history.redo()
	assert_eq(level.bonus_pockets[2].position, TULIP_1 + Vector2(20, 10))


func test_a_mirrored_drag_moves_the_twin_tulip() -> void:
	var level := _open()
	session.mirror_enabled = true
	session.set_tool(BoardEditSession.Tool.SELECT)
	_drag(TULIP_1 + Vector2(0, 4), TULIP_1 + Vector2(-10, 9))
	assert_eq(level.bonus_pockets[2].position, TULIP_1 + Vector2(-10, 5))
	assert_eq(level.bonus_pockets[3].position, TULIP_2 + Vector2(10, 5), "the twin follows")
	session.history.undo()
	assert_eq(level.bonus_pockets[3].position, TULIP_2)


func test_typing_x_on_a_mirrored_tulip_moves_its_twin_too() -> void:
	var level := _open()
	session.mirror_enabled = true
	var panel: PropertyPanel = add_child_autofree(PropertyPanel.new())
	panel.bind(session)
	session.select([_bonus("tulips", 1)] as Array[Vector2i])
	panel.refresh()
	panel.field("x").value = 200.0
	assert_eq(level.bonus_pockets[2].position, Vector2(200, 330))
	assert_eq(level.bonus_pockets[3].position, Vector2(500, 330), "the twin mirrors it, as a drag")
	panel.field("y").value = 340.0
	assert_eq(level.bonus_pockets[3].position, Vector2(500, 340))
	session.history.undo()
	session.history.undo()
	assert_eq(level.bonus_pockets[3].position, TULIP_2, "one undo step each")
	session.mirror_enabled = false
	panel.field("x").value = 210.0
	assert_eq(level.bonus_pockets[3].position, TULIP_2, "without mirror mode only the one moves")


func test_box_select_and_the_erase_tool_take_bonus_pockets() -> void:
	var level := _open()
	var box := HitTest.in_rect(level, Rect2(330, 390, 40, 160))
	assert_true(box.has(_bonus("start_pockets", 1)), "the start pocket's mouth is in the box")
	assert_true(box.has(_bonus("attackers", 1)))
	session.set_tool(BoardEditSession.Tool.ERASE)
	_press(Vector2(350, 560), true)
	_press(Vector2(350, 560), false)
	assert_eq(level.bonus_pockets.size(), 3, "the attacker is erased")
	assert_eq(ItemIds.count(level, "attackers"), 0)
	session.history.undo()
	assert_eq(level.bonus_pockets[1].role, BonusPocketSpec.Role.ATTACKER)


func test_align_and_duplicate_bonus_pockets() -> void:
	var level := _open()
	var picked: Array[Vector2i] = [_bonus("start_pockets", 1), _bonus("tulips", 1)]
	session.select(picked)
	session.commit(ArrangeAction.new(level, Arrange.align_offsets(level, picked, "top"), "Align"))
	assert_eq(level.bonus_pockets[0].position, Vector2(350, 330), "lined up on the top tulip")
	session.history.undo()
	assert_eq(level.bonus_pockets[0].position, Vector2(350, 400))
	session.select([_bonus("tulips", 2)] as Array[Vector2i])
	assert_true(EditCommands.duplicate_selection(session))
	assert_eq(ItemIds.count(level, "tulips"), 3)
	var copy: Vector2i = session.selection[0]
	assert_eq(ItemNames.name_of(level, copy), "Tulip 3", "the copy is selected, with a new id")
	assert_eq(level.bonus_pockets[copy.y].payout, 3, "a copy keeps the payout")
	var overlaps := BoardValidator.validate(level).filter(
		func(issue: BoardIssue) -> bool: return issue.message.contains("Tulip 3 overlaps")
	)
	assert_eq(overlaps.size(), 0, "the copy sits clear of the original")


func test_the_bonus_layer_hides_and_locks_bonus_pockets() -> void:
	var level := _open()
	assert_true(Layers.for_kind(BoardLevel.Kind.PACHINKO).has("Bonus pieces"))
	assert_eq(Layers.painter_mask(["Bonus pieces"] as Array[String]), BoardPainter.Layer.BONUS)
	session.set_layer("Bonus pieces", false, true)
	session.set_tool(BoardEditSession.Tool.SELECT)
	_press(TULIP_1 + Vector2(0, 4), true)
	_press(TULIP_1 + Vector2(0, 4), false)
	assert_false(session.selection.has(_bonus("tulips", 1)), "a locked layer cannot be picked")
	session.set_tool(BoardEditSession.Tool.TULIP)
	_press(TULIP_1 + Vector2(0, 4), true)
	assert_eq(level.bonus_pockets.size(), 4, "nor removed by the tulip tool")
	session.set_layer("Bonus pieces", false, false)
	session.select([_bonus("tulips", 1)] as Array[Vector2i])
	session.set_layer("Bonus pieces", true, false)
	assert_eq(session.selection.size(), 0, "hiding the layer drops its pockets from the selection")


func test_the_layers_panel_lists_bonus_pieces_with_show_and_lock() -> void:
	_open()
	var panel: LayersPanel = add_child_autofree(LayersPanel.new())
	panel.bind(session)
	var names := PackedStringArray()
	for child in panel.find_children("*", "Label", true, false):
		names.append((child as Label).text)
	assert_has(names, "Bonus pieces")
	panel.set_hidden("Bonus pieces", true)
	assert_has(session.hidden_layers, "Bonus pieces")
