extends GutTest
## The level select lists one card per board file: playable cards for the boards that load,
## greyed cards with the reason for the ones that do not.

const LevelSelectScene := preload("res://scenes/menu/level_select.tscn")
const SAVE := "user://test_level_select_save.cfg"
const EMPTY_USER_ROOT := "user://test_level_select_no_boards"

var _real_save: RefCounted = null


func before_each() -> void:
	_real_save = App.save_data
	App.settings.unlock_all_boards = true  # progression locks: tests/unit/test_maze_progress.gd


func after_each() -> void:
	App.save_data = _real_save
	App.settings.unlock_all_boards = false
	DirAccess.remove_absolute(SAVE)


func _open(kind: String) -> LevelSelect:
	App.level_select_kind = kind
	var screen := LevelSelectScene.instantiate() as LevelSelect
	# a scratch My boards folder: the tests never see the player's own boards
	screen.user_root = EMPTY_USER_ROOT
	add_child_autofree(screen)
	await wait_until(func() -> bool: return not screen.is_loading(), 20.0)
	return screen


func _playable(screen: Control) -> Array[Button]:
	var result: Array[Button] = []
	for card: Button in screen.cards():
		if not card.disabled:
			result.append(card)
	return result


func test_every_board_file_gets_a_card() -> void:
	for kind: String in ["pachinko", "maze"]:
		var expected := BoardLoader.list_boards(
			BoardLevel.Kind.MAZE if kind == "maze" else BoardLevel.Kind.PACHINKO
		)
		var screen: LevelSelect = await _open(kind)
		var cards: Array = screen.cards()
		assert_eq(cards.size(), expected.size(), kind)
		var ok_paths := PackedStringArray()
		for result in expected:
			if result.ok():
				ok_paths.append(result.path)
		var shown := PackedStringArray()
		for card in _playable(screen):
			shown.append(str(card.get("board_path")))
		shown.sort()  # mazes are listed in the order they open (MazeProgress)
		assert_eq(shown, ok_paths, "exactly the boards that load are playable (%s)" % kind)
		assert_gt(shown.size(), 0, "the shipped %s boards load" % kind)


func test_broken_board_is_listed_greyed_with_its_error() -> void:
	var screen: LevelSelect = await _open("maze")
	var good := BoardLoader.list_boards(BoardLevel.Kind.MAZE)
	var broken := BoardLoader.load_board("res://levels/maze/does_not_exist.board")
	var results: Array[BoardLoadResult] = []
	results.append_array(good)
	results.append(
		BoardLoader.load_board("res://tests/fixtures/boards/catalog/pachinko/b_broken.board")
	)
	results.append(broken)
	screen.show_boards(results)
	var cards: Array = screen.cards()
	assert_eq(cards.size(), good.size() + 2)
	assert_true((cards[-2] as Button).disabled, "a damaged file is listed, greyed")
	var last: LevelCard = cards[-1]
	assert_true(last.disabled, "a broken board cannot start")
	assert_eq(last.focus_mode, Control.FOCUS_ALL, "its reason is reachable by keyboard")
	assert_string_contains(last.tooltip_text, "does not exist")
	assert_string_contains(" ".join(last.texts()), "does_not_exist.board")
	assert_string_contains(str((screen.get_node("%SummaryLabel") as Label).text), "2 could not")


func test_first_playable_card_takes_focus() -> void:
	var screen: LevelSelect = await _open("pachinko")
	var first: Button = screen.first_card()
	assert_not_null(first)
	assert_true(first.has_focus())


func _card_texts(screen: Control) -> PackedStringArray:
	return (screen.first_card() as LevelCard).texts()


func test_best_results_are_shown_on_the_cards() -> void:
	var scratch := SaveData.new()
	scratch.load_file(SAVE)
	App.save_data = scratch
	var pachinko_id := BoardLoader.list_boards(BoardLevel.Kind.PACHINKO)[0].level.board_id
	var mazes := MazeProgress.sorted(BoardLoader.list_boards(BoardLevel.Kind.MAZE))
	var maze_id := mazes[0].level.board_id
	assert_has(
		_card_texts(await _open("pachinko")),
		"Nothing won yet",
		"a pachinko board's record is the most balls won, as the panel says"
	)
	assert_has(
		_card_texts(await _open("maze")),
		"No finish yet",
		"a maze never finished (the save keeps no attempts: true whether played or not)"
	)
	App.record_pachinko_balls(pachinko_id, 23)
	App.record_maze_time(maze_id, false, 101.34)
	assert_has(_card_texts(await _open("pachinko")), "Most won: 23 balls")
	assert_has(_card_texts(await _open("maze")), "Best time: 1:41.3", "the maze clock's m:ss.t")
