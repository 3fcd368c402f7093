extends GutTest
## The level select without a mouse: the arrows go card to card (never onto a card's file
## buttons), My boards is reached the same way, a card's own menu offers Play / Export /
## Delete, the focused card shows its whole description, and Delete keeps the player's place.

const LevelSelectScene := preload("res://scenes/menu/level_select.tscn")
const ROOT := "user://test_level_select_keys"
const CLASSIC := "res://levels/pachinko/classic.board"
const THEME := preload("res://scenes/menu/ui_theme.tres")
## A description far longer than a card shows when it is not focused.
const LONG_DESCRIPTION := (
	"A tall machine: three rows of tulips, then a wide fan of pins that sends a strong shot"
	+ " across the top to the far pockets."
)


func before_each() -> void:
	_remove_tree(ROOT)
	DirAccess.make_dir_recursive_absolute(ROOT + "/pachinko")


func after_all() -> void:
	_remove_tree(ROOT)


func _copy(target_name: String, description := "") -> String:
	var text := FileAccess.get_file_as_string(CLASSIC)
	if not description.is_empty():
		# whatever Classic's own description says today, this one takes its place
		var line := RegEx.create_from_string('"description": "[^"]*"')
		text = line.sub(text, '"description": "%s"' % description)
	var target := "%s/pachinko/%s" % [ROOT, target_name]
	var file := FileAccess.open(target, FileAccess.WRITE)
	file.store_string(text)
	file.close()
	return target


func _open() -> LevelSelect:
	App.level_select_kind = "pachinko"
	var screen := LevelSelectScene.instantiate() as LevelSelect
	screen.user_root = ROOT
	add_child_autofree(screen)
	await wait_until(func() -> bool: return not screen.is_loading(), 20.0)
	await wait_physics_frames(2)
	return screen


func _neighbour(card: Control, side: Side) -> Control:
	var path := card.get_focus_neighbor(side)
	return card.get_node_or_null(path) as Control if not path.is_empty() else null


func _press(action: StringName) -> void:
	for pressed: bool in [true, false]:
		var event := InputEventAction.new()
		event.action = action
		event.pressed = pressed
		Input.parse_input_event(event)
		await get_tree().process_frame
	await get_tree().process_frame


func test_arrows_go_card_to_card_and_reach_my_boards() -> void:
	_copy("a_mine.board")
	_copy("b_mine.board")
	var screen: LevelSelect = await _open()
	var cards: Array = screen.cards()
	assert_eq(cards.size(), 7, "five shipped boards and two of mine")
	var columns: int = (screen.get_node("%Cards") as GridContainer).columns
	assert_eq(columns, (screen.get_node("%MyCards") as GridContainer).columns, "grids line up")
	var left := (cards[0] as Control).global_position.x
	assert_eq((cards[5] as Control).global_position.x, left, "My boards start under the first")
	assert_eq((cards[6] as Control).global_position.x, (cards[1] as Control).global_position.x)
	for i in cards.size():
		var card: Control = cards[i]
		var below := _neighbour(card, SIDE_BOTTOM)
		assert_true(below in cards, "Down from card %d lands on a card" % i)
		for side: Side in [SIDE_LEFT, SIDE_RIGHT, SIDE_TOP]:
			var next := _neighbour(card, side)
			assert_true(next == null or next in cards, "no arrow leads to a file button")
	assert_eq(_neighbour(cards[0], SIDE_BOTTOM), cards[columns], "Down: the card below")
	assert_eq(_neighbour(cards[columns], SIDE_BOTTOM), cards[5], "on into My boards")
	assert_eq(_neighbour(cards[5], SIDE_TOP), cards[columns], "and Up back again")
	assert_eq(_neighbour(cards[columns - 1], SIDE_RIGHT), cards[columns], "Right wraps a row")
	# and the real events: Down twice from the first card is my first board
	(cards[0] as Control).grab_focus()
	await _press(&"ui_down")
	await _press(&"ui_down")
	assert_eq(get_viewport().gui_get_focus_owner(), cards[5], "two presses to My boards")
	for slot: Node in screen.my_slots():
		assert_eq((slot.export_button() as Button).focus_mode, Control.FOCUS_NONE)


func test_a_cards_menu_offers_play_export_and_delete() -> void:
	var mine := _copy("mine.board")
	var screen: LevelSelect = await _open()
	var menu: PopupMenu = screen.card_menu()
	(screen.first_card() as Control).grab_focus()
	await _press(&"board_actions")
	assert_true(menu.visible, "X / Square opens the focused card's menu")
	assert_eq(menu.entries(), PackedStringArray(["Play", "Export a copy…"]))
	assert_eq(menu.theme, THEME, "in the game's theme")
	menu.hide()
	var my_card: Control = (screen.my_slots() as Array)[0].get("card")
	my_card.grab_focus()
	await _press(&"board_actions")
	assert_eq(menu.entries(), PackedStringArray(["Play", "Export a copy…", "Delete…"]))
	menu.id_pressed.emit(1)  # Export a copy…
	var dialogs: Node = screen.get_node("%Dialogs")
	var export_dialog: FileDialog = dialogs.export_dialog()
	assert_true(export_dialog.visible, "the export asks where, in a file dialog")
	assert_eq(export_dialog.current_file, mine.get_file(), "showing the file's name")
	assert_eq(export_dialog.theme, THEME)
	var room := get_viewport().get_visible_rect().size
	assert_true(export_dialog.size.x <= room.x and export_dialog.size.y <= room.y, "fits")
	export_dialog.hide()


# A play trial: the focused card's picture and name sat 6 px higher than its neighbours'
# (its thumbnail gave up height for the whole description). The row lines up now; a longer
# description reads through on the focused card (the next test).
func test_the_focused_card_lines_up_with_its_neighbours() -> void:
	_copy("long.board", " ".join(PackedStringArray([LONG_DESCRIPTION, LONG_DESCRIPTION])))
	var screen: LevelSelect = await _open()
	var card: Control = (screen.my_slots() as Array)[0].get("card")
	var text: RefCounted = card.long_text()
	var label: Label = text.get("label")
	assert_false(text.shows_whole_text(), "unfocused, a long description is cut")
	var resting_size := card.size
	var resting_top := label.global_position.y - card.global_position.y
	card.grab_focus()
	await wait_physics_frames(3)
	assert_eq(
		label.global_position.y - card.global_position.y, resting_top, "its words do not move"
	)
	assert_eq(card.size, resting_size, "the card keeps its size (nothing moves)")
	assert_true(text.reads_through(), "the rest of the description reads through")


func test_a_description_too_long_for_the_card_reads_through() -> void:
	var longest := " ".join(
		PackedStringArray([LONG_DESCRIPTION, LONG_DESCRIPTION, LONG_DESCRIPTION])
	)
	_copy("longest.board", longest)
	var screen: LevelSelect = await _open()
	var card: Control = (screen.my_slots() as Array)[0].get("card")
	var text: RefCounted = card.long_text()
	card.grab_focus()
	await wait_physics_frames(3)
	assert_true(text.reads_through(), "%d lines cannot show at once" % text.wrapped_lines())
	assert_false(text.shows_last_line())
	for step in 40:
		text.advance(0.5)
		if text.shows_last_line():
			break
	assert_true(text.shows_last_line(), "the text moves on to its last line")
	for step in 40:
		text.advance(0.5)
		if (text.get("label") as Label).lines_skipped == 0:
			break
	assert_eq((text.get("label") as Label).lines_skipped, 0, "and starts again from the top")


func test_delete_keeps_the_players_place() -> void:
	for i in 7:
		_copy("board_%d.board" % i)
	var screen: LevelSelect = await _open()
	var slots: Array = screen.my_slots()
	var doomed: Control = slots[4].get("card")
	var next_path := str(slots[5].get("card").get("board_path"))
	doomed.grab_focus()
	await wait_physics_frames(3)
	var scroll: ScrollContainer = screen.get_node("%Scroll")
	var before := scroll.scroll_vertical
	assert_gt(before, 0, "the list is scrolled down to the card")
	screen.delete_board(str(doomed.get("board_path")))
	await wait_until(func() -> bool: return not screen.is_loading(), 20.0)
	await wait_physics_frames(3)
	var focused := get_viewport().gui_get_focus_owner()
	assert_eq(str(focused.get("board_path")) if focused != null else "", next_path)
	assert_almost_eq(float(scroll.scroll_vertical), float(before), 60.0, "still scrolled there")


func test_the_delete_question_names_a_refused_file_once() -> void:
	var broken := "%s/pachinko/broken.board" % ROOT
	var file := FileAccess.open(broken, FileAccess.WRITE)
	file.store_string("not a board")
	file.close()
	var screen: LevelSelect = await _open()
	var slot: Node = (screen.my_slots() as Array)[0]
	var dialogs: Node = screen.get_node("%Dialogs")
	screen.open_card_menu(slot.get("card"))
	var menu: PopupMenu = screen.card_menu()
	assert_true(menu.is_item_disabled(0), "a board that did not load offers Play greyed")
	assert_eq(menu.entries()[2], "Delete…", "but it can be deleted")
	menu.hide()
	dialogs.ask_delete(broken, slot.shown_name())
	var question := str(dialogs.delete_question())
	assert_eq(question.count("broken.board"), 1, question)
	(dialogs.open_dialog() as Window).hide()


func test_a_refused_file_and_a_message_move_nothing() -> void:
	var screen: LevelSelect = await _open()
	var header: Control = screen.get_node("%TitleLabel").get_parent()
	var scroll: Control = screen.get_node("%Scroll")
	var card := screen.first_card()
	# the footer's status line appears with the message (no empty band before it): the list
	# gives up room at its foot, but the header, the list's top and its cards stay put
	var before := [header.get_global_rect(), scroll.global_position, card.global_position]
	var broken := "%s/pachinko/broken.board" % ROOT
	var file := FileAccess.open(broken, FileAccess.WRITE)
	file.store_string("not a board")
	file.close()
	var refused := ProjectSettings.globalize_path(broken)
	screen.import_files(PackedStringArray([refused, refused]))
	await wait_until(func() -> bool: return not screen.is_loading(), 20.0)
	await wait_physics_frames(3)
	var summary := str((screen.get_node("%SummaryLabel") as Label).text)
	assert_string_contains(summary, "could not be loaded", "the refused file is listed")
	assert_ne(str((screen.get_node("%StatusLabel") as Label).text), "", "and a message shows")
	var after := [header.get_global_rect(), scroll.global_position, card.global_position]
	assert_eq(after, before, "nothing moved")


static func _remove_tree(path: String) -> void:
	if not DirAccess.dir_exists_absolute(path):
		return
	for folder in DirAccess.get_directories_at(path):
		_remove_tree(path.path_join(folder))
	for file_name in DirAccess.get_files_at(path):
		DirAccess.remove_absolute(path.path_join(file_name))
	DirAccess.remove_absolute(path)


# A play trial went back to the list from Hanami and found Classic focused: the board last
# played takes the focus, a shipped one and one of the player's own alike.
func test_the_board_last_played_takes_the_focus() -> void:
	var mine := _copy("a_mine.board")
	var kept := App.last_board_path("pachinko")
	for played: String in ["res://levels/pachinko/hanami.board", mine]:
		App.request_board("pachinko", played)
		var screen: LevelSelect = await _open()
		var focused := get_viewport().gui_get_focus_owner()
		assert_true(focused is LevelCard, "a card has the focus")
		if focused is LevelCard:
			assert_eq((focused as LevelCard).board_path, played, "the board last played")
		screen.free()
	App.request_board("pachinko", kept if not kept.is_empty() else CLASSIC)
