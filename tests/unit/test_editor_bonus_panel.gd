extends GutTest
## The Selection panel for a bonus pocket: its mouth, size and payout, a start pocket's reel
## symbols, an attacker's open seconds and catches, shown with exact values and each typed
## value one undo step; a value the game cannot use is named by the pocket's id; the role
## picker turns one kind of bonus pocket into another.

## A frozen bonus board (the first Fever layout), so rebalancing the shipped boards never
## moves the pieces these tests pick.
const BONUS_BOARD := "res://tests/fixtures/boards/bonus_layout.board"
const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const PropertyPanel := preload("res://addons/board_editor/ui/property_panel.gd")
const BoardDock := preload("res://addons/board_editor/ui/board_dock.gd")

var session: BoardEditSession
var panel: PropertyPanel


# fever.board: start pocket 1, attacker 1, tulips 1 and 2 (bonus_pockets 0 to 3).
func _select(index: int) -> BoardLevel:
	var level := (load(BONUS_BOARD) as BoardLevel).duplicate_level()
	session = BoardEditSession.new(level)
	panel = add_child_autofree(PropertyPanel.new())
	panel.bind(session)
	session.select([BoardItems.make(BoardItems.Kind.BONUS, index)] as Array[Vector2i])
	panel.refresh()
	return level


func _shown(key: String) -> bool:
	return panel.field(key).get_parent().visible


func test_an_attackers_fields_show_and_each_edit_is_one_undo_step() -> void:
	var level := _select(1)
	assert_eq(panel.title(), "Attacker 1 at (350, 540)")
	assert_eq(panel.field("open_seconds").value, 8.0)
	assert_eq(panel.field("open_catches").value, 10.0)
	assert_eq(panel.field("width").value, 64.0)
	assert_false(_shown("symbols"), "reel symbols belong to start pockets")
	panel.field("open_seconds").value = 12.5
	panel.field("open_catches").value = 6
	panel.field("payout").value = 20
	var attacker := level.bonus_pockets[1]
	assert_eq([attacker.open_seconds, attacker.open_catches, attacker.payout], [12.5, 6, 20])
	session.history.undo()
	assert_eq(attacker.payout, 12, "one undo takes back only the payout")
	assert_eq(attacker.open_catches, 6)
	session.history.undo()
	session.history.undo()
	assert_eq([attacker.open_seconds, attacker.open_catches], [8.0, 10])
	panel.refresh()  # the dock refreshes it on every board change
	assert_eq(panel.field("open_seconds").value, 8.0, "the panel shows the undone value")


func test_a_start_pockets_symbols_and_a_tulips_exact_position() -> void:
	var level := _select(0)
	assert_eq(panel.field("symbols").value, 3.0)
	assert_false(_shown("open_seconds"))
	panel.field("symbols").value = 7
	assert_eq(level.bonus_pockets[0].symbols, 7)
	session.select([BoardItems.make(BoardItems.Kind.BONUS, 3)] as Array[Vector2i])
	panel.refresh()
	assert_eq(panel.title(), "Tulip 2 at (485, 330)")
	assert_false(_shown("symbols"), "a tulip has no reels")
	panel.field("x").value = 470.5
	panel.field("width").value = 30
	assert_eq(level.bonus_pockets[3].position, Vector2(470.5, 330))
	assert_eq(level.bonus_pockets[3].width, 30.0)
	session.history.undo()
	session.history.undo()
	assert_eq(level.bonus_pockets[3].position, Vector2(485, 330))
	assert_eq(level.bonus_pockets[0].symbols, 7, "the symbols edit is its own step")


func test_a_too_narrow_tulip_is_named_by_its_id() -> void:
	var level := _select(3)
	panel.field("width").value = 8
	var messages := PackedStringArray()
	for issue in BoardValidator.errors(level):
		messages.append(issue.message)
	assert_string_contains("\n".join(messages), "Tulip 2 is 8 px wide; a ball needs at least 12.")


func test_the_dock_counts_the_bonus_layer_on_a_pachinko_board_only() -> void:
	var level := _select(0)
	assert_string_contains(
		BoardDock.count_text(level), "Start pockets: 1   Attackers: 1   Tulips: 2"
	)
	var maze := load("res://levels/maze/catacombs.board") as BoardLevel
	assert_eq(BoardDock.count_text(maze), "Walls: 47   Holes: 6   Ball starts: 4")


func test_the_role_picker_turns_a_tulip_into_a_start_pocket_in_one_undo_step() -> void:
	var level := _select(3)
	var tulip := level.bonus_pockets[3]
	assert_true(panel.role_picker().get_parent().visible, "a bonus pocket shows its role")
	assert_eq(panel.role_picker().selected, BonusPocketSpec.Role.TULIP)
	panel.role_picker().select(BonusPocketSpec.Role.START)
	panel.role_picker().item_selected.emit(BonusPocketSpec.Role.START)
	var roles: Array = level.bonus_pockets.map(func(s: BonusPocketSpec) -> int: return s.role)
	assert_eq(roles, [0, 0, 1, 2], "the new start pocket sits with the start pockets")
	var made := level.bonus_pockets[1]
	assert_eq([made.position, made.width, made.payout], [tulip.position, tulip.width, tulip.payout])
	assert_eq(session.selection, [BoardItems.make(BoardItems.Kind.BONUS, 1)] as Array[Vector2i])
	assert_eq(panel.title(), "Start pocket 2 at (485, 330)", "a fresh id in its new list")
	assert_true(_shown("symbols"), "a start pocket has reels")
	assert_eq(session.history.names(), PackedStringArray(["Make bonus pocket a start pocket"]))
	session.history.undo()
	assert_eq(level.bonus_pockets[3], tulip, "undo brings back the very same tulip")
	assert_eq(tulip.role, BonusPocketSpec.Role.TULIP)
	assert_eq(ItemIds.of_bonus(level, 3), 2, "under its own id")


func test_picking_the_same_role_or_a_pin_changes_nothing() -> void:
	var level := _select(1)
	panel.set_role(BonusPocketSpec.Role.ATTACKER)
	assert_eq(session.history.names().size(), 0)
	session.select([BoardItems.make(BoardItems.Kind.PIN, 0)] as Array[Vector2i])
	panel.refresh()
	assert_false(panel.role_picker().get_parent().visible, "a pin has no role")
	panel.set_role(BonusPocketSpec.Role.TULIP)
	assert_eq(session.history.names().size(), 0)
	assert_eq(level.bonus_pockets[1].role, BonusPocketSpec.Role.ATTACKER)


func test_the_problem_list_comes_before_the_selection_panel() -> void:
	var dock: BoardDock = add_child_autofree(BoardDock.new())
	var problems := dock.problems()
	var selection := dock.properties()
	assert_eq(problems.get_parent(), selection.get_parent(), "both in the dock's one body")
	assert_lt(problems.get_index(), selection.get_index(), "the problems sit above")
	assert_true(dock.body().is_ancestor_of(problems), "and scroll with it")
