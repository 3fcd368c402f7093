extends GutTest
## The level select lists one card per board file: playable cards for the boards that load,
## greyed cards with the reason for the ones that do not.

const LevelSelectScene := preload("res://scenes/menu/level_select.tscn")


func _open(kind: String) -> Control:
	App.level_select_kind = kind
	var screen := LevelSelectScene.instantiate() as Control
	add_child_autofree(screen)
	return screen


func _playable(screen: Control) -> Array[Button]:
	var result: Array[Button] = []
	for card: Button in screen.call("cards"):
		if not card.disabled:
			result.append(card)
	return result


func test_every_board_file_gets_a_card() -> void:
	for kind: String in ["pachinko", "maze"]:
		var expected := BoardLoader.list_boards(
			BoardLevel.Kind.MAZE if kind == "maze" else BoardLevel.Kind.PACHINKO
		)
		var screen := _open(kind)
		var cards: Array = screen.call("cards")
		assert_eq(cards.size(), expected.size(), kind)
		var ok_paths := PackedStringArray()
		for result in expected:
			if result.ok():
				ok_paths.append(result.path)
		var shown := PackedStringArray()
		for card in _playable(screen):
			shown.append(str(card.get("board_path")))
		assert_eq(shown, ok_paths, "exactly the boards that load are playable (%s)" % kind)
		assert_gt(shown.size(), 0, "the shipped %s boards load" % kind)


func test_broken_board_is_listed_greyed_with_its_error() -> void:
	var screen := _open("maze")
	var good := BoardLoader.list_boards(BoardLevel.Kind.MAZE)
	var broken := BoardLoader.load_board("res://levels/maze/does_not_exist.tres")
	var results: Array[BoardLoadResult] = []
	results.append_array(good)
	results.append(broken)
	screen.call("show_boards", results)
	var cards: Array = screen.call("cards")
	assert_eq(cards.size(), good.size() + 1)
	var last: Button = cards[-1]
	assert_true(last.disabled, "a broken board cannot start")
	assert_eq(last.focus_mode, Control.FOCUS_ALL, "its reason is reachable by keyboard")
	assert_string_contains(last.tooltip_text, "does not exist")
	var texts := PackedStringArray()
	for label in last.find_children("*", "Label", true, false):
		texts.append((label as Label).text)
	assert_string_contains(" ".join(texts), "does_not_exist.tres")
	assert_string_contains(str((screen.get_node("%SummaryLabel") as Label).text), "1 could not")


func test_first_playable_card_takes_focus() -> void:
	var screen := _open("pachinko")
	var first: Button = screen.call("first_card")
	assert_not_null(first)
	assert_true(first.has_focus())


func test_best_result_is_shown_on_the_card() -> void:
	var results := BoardLoader.list_boards(BoardLevel.Kind.PACHINKO)
	var board_id := results[0].level.board_id
	var best := App.best_pachinko_balls(board_id)
	var screen := _open("pachinko")
	var texts := PackedStringArray()
	for label in (screen.call("first_card") as Button).find_children("*", "Label", true, false):
		texts.append((label as Label).text)
	var expected := "Not played yet" if best < 0 else "Best: %d balls won" % best
	assert_has(texts, expected)
