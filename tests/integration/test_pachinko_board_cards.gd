extends GutTest
## Trial 6: Windmills' card in the pachinko board list ended "…and a ×1…" at 1280 × 720.
## Every pachinko card shows its whole description, focused or not.

const LevelSelectScene := preload("res://scenes/menu/level_select.tscn")
const StretchedWindow := preload("res://tests/integration/stretched_window.gd")
const NO_BOARDS := "user://test_pachinko_board_cards_no_boards"


func after_each() -> void:
	App.level_select_kind = BoardLevel.PACHINKO_NAME


func test_every_pachinko_card_shows_its_whole_description_at_1280_by_720() -> void:
	App.level_select_kind = BoardLevel.PACHINKO_NAME
	var no_boards := func(node: Node) -> void: node.set("user_root", NO_BOARDS)
	var node: Node = await StretchedWindow.open(
		self, LevelSelectScene, Vector2i(1280, 720), 1, no_boards
	)
	var screen := node as LevelSelect
	await wait_until(func() -> bool: return not screen.is_loading(), 20.0)
	await wait_process_frames(4)
	var cards := 0
	for button in screen.cards():
		var card := button as LevelCard
		if card == null or card.long_text() == null:
			continue
		cards += 1
		var text := card.long_text()
		assert_true(
			text.shows_whole_text(),
			"%s: %d lines, %d shown" % [card.name, text.wrapped_lines(), text._visible_lines()]
		)
	assert_gte(cards, 5, "the five machines")
	screen.free()  # before its window
