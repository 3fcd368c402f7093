extends GutTest
## The level select with the player's own boards: every file in My boards gets a card (the
## hostile corpus greyed with its reasons), a board that takes 5 s to load never stops the
## screen, and import / delete through the screen update the list.

const LevelSelectScene := preload("res://scenes/menu/level_select.tscn")
const HOSTILE := "res://tests/fixtures/hostile_boards/pachinko"
const GOOD := "res://levels/pachinko/classic.board"
const ROOT := "user://test_level_select_my_boards"
## The 10,000-file folder (its own, so removing it never races the other tests' folder).
const MANY_ROOT := "user://test_level_select_many_boards"
const MARKER := "user://hostile_payload_ran.txt"
## How long the slow test board takes to load.
const SLOW_MS := 5000


func before_each() -> void:
	_remove_tree(ROOT)
	DirAccess.make_dir_recursive_absolute(ROOT + "/pachinko")


func after_all() -> void:
	_remove_tree(ROOT)


func _copy(source: String, target_name: String) -> String:
	var target := "%s/pachinko/%s" % [ROOT, target_name]
	var file := FileAccess.open(target, FileAccess.WRITE)
	file.store_buffer(FileAccess.get_file_as_bytes(source))
	file.close()
	return target


func _open(load_one := Callable()) -> LevelSelect:
	App.level_select_kind = "pachinko"
	var screen := LevelSelectScene.instantiate() as LevelSelect
	screen.user_root = ROOT
	screen.load_one = load_one
	add_child_autofree(screen)
	return screen


func _loaded(screen: Control, seconds := 20.0) -> void:
	await wait_until(func() -> bool: return not screen.is_loading(), seconds)


func test_every_hostile_file_is_listed_and_the_refused_ones_greyed() -> void:
	DirAccess.remove_absolute(ProjectSettings.globalize_path(MARKER))
	for file_name in DirAccess.get_files_at(HOSTILE):
		_copy("%s/%s" % [HOSTILE, file_name], file_name)
	_copy(GOOD, "mine.board")
	var expected := BoardLoader.list_boards(BoardLevel.Kind.PACHINKO, ROOT)
	var screen := _open()
	await _loaded(screen)
	var slots: Array = screen.my_slots()
	assert_eq(slots.size(), expected.size(), "one card per file in My boards")
	assert_gt(expected.size(), 15, "the hostile corpus is there")
	var refused := 0
	for index in expected.size():
		var card: LevelCard = slots[index].get("card")
		var result: BoardLoadResult = expected[index]
		assert_eq(str(card.get("board_path")), result.path)
		assert_eq(card.disabled, not result.ok(), result.path)
		if not result.ok():
			refused += 1
			var words := " ".join(card.texts())
			assert_string_contains(words, result.path.get_file(), "the card names its file")
			assert_string_contains(card.tooltip_text, result.error)
	assert_gt(refused, 10, "hostile boards are greyed")
	assert_false(FileAccess.file_exists(MARKER), "no payload ran")
	var summary := str((screen.get_node("%SummaryLabel") as Label).text)
	assert_string_contains(summary, "%d could not be loaded" % refused)


func test_a_board_that_takes_5_seconds_does_not_stop_the_screen() -> void:
	_copy(GOOD, "a_fine.board")
	_copy(GOOD, "slow.board")
	_copy(GOOD, "z_fine.board")
	var slow_load := func(path: String, kind: int, root: String) -> BoardLoadResult:
		if path.ends_with("slow.board"):
			OS.delay_msec(SLOW_MS)
		return BoardLoader.load_listed(path, kind, root)
	var screen := _open(slow_load)
	var began := Time.get_ticks_msec()
	var frames := 0
	while Time.get_ticks_msec() - began < 1500:
		await get_tree().process_frame
		frames += 1
	assert_true(screen.is_loading(), "the slow board is still loading")
	assert_gt(frames, 20, "the screen kept drawing frames while a board took 5 s")
	var slots: Array = screen.my_slots()
	var slow_card: LevelCard = slots[1].get("card")
	assert_true(slow_card.get("loading"), "the slow board's card says it is loading")
	assert_string_contains(" ".join(slow_card.texts()), "Loading")
	assert_false(slots[2].get("card").get("loading"), "the board after it filled in already")
	# the screen still takes input while the board loads: Tab moves the focus
	var focus_before := get_viewport().gui_get_focus_owner()
	var tab := InputEventKey.new()
	tab.keycode = KEY_TAB
	tab.pressed = true
	Input.parse_input_event(tab)
	await get_tree().process_frame
	await get_tree().process_frame
	assert_ne(get_viewport().gui_get_focus_owner(), focus_before, "the focus moved")
	await _loaded(screen, SLOW_MS / 1000.0 + 5.0)
	assert_false(screen.is_loading())
	assert_false(slow_card.disabled, "the slow board became playable once loaded")


func test_import_and_delete_through_the_screen() -> void:
	var screen := _open()
	await _loaded(screen)
	assert_eq(screen.my_slots().size(), 0)
	assert_true((screen.get_node("%MyBoardsEmpty") as Label).visible, "the empty hint shows")
	var source := ProjectSettings.globalize_path(GOOD)
	screen.import_files(PackedStringArray([source, source]))
	await _loaded(screen)
	var slots: Array = screen.my_slots()
	assert_eq(slots.size(), 2, "the same file imported twice gets two names")
	var status := str((screen.get_node("%StatusLabel") as Label).text)
	assert_string_contains(status, "classic.board")
	assert_string_contains(status, "classic_2.board")
	var card: Button = slots[0].get("card")
	assert_false(card.disabled, "an imported board is playable")
	assert_not_null(slots[0].delete_button(), "My boards can be deleted")
	screen.delete_board(str(card.get("board_path")))
	await _loaded(screen)
	assert_eq(screen.my_slots().size(), 1)
	assert_true(FileAccess.file_exists(GOOD), "the shipped board is untouched")


func test_an_import_runs_off_the_main_thread() -> void:
	var screen := _open()
	await _loaded(screen)
	var source := ProjectSettings.globalize_path(GOOD)
	screen.import_files(PackedStringArray([source]))
	var status := screen.get_node("%StatusLabel") as Label
	assert_eq(status.text, "Importing 1 file…", "the call returns before the file is checked")
	assert_true(screen.is_loading(), "the screen waits for the import like a loading")
	await _loaded(screen)
	assert_string_contains(status.text, 'Imported "Classic" into My boards as classic.board')
	assert_eq(screen.my_slots().size(), 1)


func test_ten_thousand_files_list_the_first_few_hundred_and_say_so() -> void:
	var folder := MANY_ROOT + "/pachinko"
	_remove_tree(MANY_ROOT)
	DirAccess.make_dir_recursive_absolute(folder)
	for index in 10000:
		FileAccess.open("%s/f%05d.board" % [folder, index], FileAccess.WRITE).close()
	App.level_select_kind = "pachinko"
	var screen := LevelSelectScene.instantiate() as LevelSelect
	screen.user_root = MANY_ROOT
	add_child_autofree(screen)
	var listed := LevelSelect.MAX_LISTED
	var first_frame := screen.my_slots().size()
	assert_eq(first_frame, LevelSelect.SLOTS_PER_FRAME, "the first frame makes only a few cards")
	await _loaded(screen)
	assert_eq(screen.my_slots().size(), listed, "only the first files get a card")
	var summary := (screen.get_node("%SummaryLabel") as Label).text
	assert_string_contains(summary, "; %d more files not listed" % (10000 - listed))
	var slots := screen.my_slots()
	assert_eq(str(slots[0].card.get("board_path")).get_file(), "f00000.board")
	assert_true(slots.all(func(slot: LevelSlot) -> bool: return slot.card.disabled), "all empty")
	_remove_tree(MANY_ROOT)


func test_shipped_boards_offer_export_but_never_delete() -> void:
	var screen := _open()
	await _loaded(screen)
	var first: Button = screen.first_card()
	var slot := first.get_parent() as LevelSlot
	assert_not_null(slot.export_button())
	assert_null(slot.delete_button(), "a shipped board has no delete button")


func test_a_refused_import_writes_nothing_and_says_why() -> void:
	var screen := _open()
	await _loaded(screen)
	var hostile := ProjectSettings.globalize_path(HOSTILE + "/object_in_field.board")
	screen.import_files(PackedStringArray([hostile]))
	await _loaded(screen)
	assert_eq(DirAccess.get_files_at(ROOT + "/pachinko").size(), 0, "nothing copied")
	var status := str((screen.get_node("%StatusLabel") as Label).text)
	assert_string_contains(status, "Not imported: object_in_field.board")


func test_a_file_dropped_on_the_window_is_imported() -> void:
	var screen := _open()
	await _loaded(screen)
	var source := ProjectSettings.globalize_path("res://levels/maze/catacombs.board")
	get_window().files_dropped.emit(PackedStringArray([source]))
	await _loaded(screen)
	assert_true(FileAccess.file_exists(ROOT + "/maze/catacombs.board"), "copied to the maze folder")
	var status := str((screen.get_node("%StatusLabel") as Label).text)
	assert_string_contains(status, "a maze board: find it in the Tilt Maze list")


static func _remove_tree(path: String) -> void:
	if not DirAccess.dir_exists_absolute(path):
		return
	for folder in DirAccess.get_directories_at(path):
		_remove_tree(path.path_join(folder))
	for file_name in DirAccess.get_files_at(path):
		DirAccess.remove_absolute(path.path_join(file_name))
	DirAccess.remove_absolute(path)
