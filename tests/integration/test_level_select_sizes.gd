extends GutTest
## The maze level select at 720 × 1280, 900 × 700 and 1280 × 720, as a player sees it.
## QA found the cards' medal times and "Locked: finish … first" drawn 11 px on a portrait
## phone (10.5 px at 900 × 700): they now grow to 14 screen px and are laid out by the
## measured text, so they still fit the card (which grows as much, keeping its
## description). The footer kept a blank two-line band for a status message that was empty
## nearly always, and the cards sat in a narrow block with empty bands either side: now the
## status line shows only with something to say, and the cards share the row's width.

const MazeLevelSelectWindow := preload("res://tests/integration/maze_level_select_window.gd")
const ScratchSave := preload("res://tests/helpers/scratch_save.gd")
const SIZES: Array[Vector2i] = [Vector2i(720, 1280), Vector2i(900, 700), Vector2i(1280, 720)]
const EMPTY_USER_ROOT := "user://test_level_select_sizes_no_boards"
const SAVE := "user://test_level_select_sizes_save.cfg"

var _real_save: RefCounted = null


func before_each() -> void:
	# a fresh save: Garden Path open and played by no one, the next boards locked
	_real_save = ScratchSave.swap_in(SAVE)


func after_each() -> void:
	ScratchSave.restore(_real_save, SAVE)
	App.level_select_kind = BoardLevel.PACHINKO_NAME


## The maze level select in a window of `size` pixels, stretched as the project stretches.
func _open_in_window(size: Vector2i) -> LevelSelect:
	return await MazeLevelSelectWindow.open(self, size, EMPTY_USER_ROOT)


func test_medal_times_and_locks_read_at_14_px_and_fit_the_card() -> void:
	for size in SIZES:
		var screen := await _open_in_window(size)
		var medals := 0
		var locks := 0
		for button in screen.cards():
			var badges := (button as LevelCard).medal_badges()
			if badges == null:
				continue
			var card := button as LevelCard
			var description := card.long_text().label
			assert_gte(
				description.get_visible_line_count(),
				1,
				"%s: %s keeps a line of its description beside the grown row" % [size, card.name]
			)
			var px := badges.font_size() * badges.screen_px_per_font_unit()
			assert_gte(px, 14.0, "%s: %s's medal row is %.1f px" % [size, button.name, px])
			if badges.lock_text.is_empty():
				medals += 1
				assert_lte(
					badges.rows_width(),
					badges.size.x + 0.5,
					"%s: %s's times fit the card" % [size, button.name]
				)
			else:
				locks += 1
				assert_between(
					badges.lock_lines(), 1, 2, "%s: %s's lock text" % [size, button.name]
				)
		assert_gte(medals, 1, "%s: Garden Path shows its times" % size)
		assert_gte(locks, 10, "%s: the locked boards say what opens them" % size)
		screen.free()  # before its window


func test_the_footer_has_no_empty_band_until_there_is_news() -> void:
	for size in SIZES:
		var screen := await _open_in_window(size)
		var footer := screen.get_node("Margin/Box/Footer") as Control
		var hint := screen.get_node("%Hint") as Label
		var status := screen.get_node("%StatusLabel") as Label
		assert_false(status.visible, "%s: no message, no status line" % size)
		var padding := footer.size.y - hint.size.y
		assert_lt(
			padding, 40.0, "%s: the footer is the hint and its edge (%.0f more)" % [size, padding]
		)
		screen.export_board("res://levels/maze/nowhere.board", "user://nowhere/at/all.board")
		await wait_process_frames(2)
		assert_true(status.visible, "%s: a message shows" % size)
		assert_gt(status.size.y, 0.0)
		screen.free()


func test_the_cards_share_the_width_of_the_list() -> void:
	for size in SIZES:
		var screen := await _open_in_window(size)
		var scroll := screen.get_node("%Scroll") as ScrollContainer
		var grid := screen.get_node("%Cards") as GridContainer
		var first := screen.cards()[0].get_global_rect()
		var row_end := first.position.x
		for button in screen.cards().slice(0, grid.columns):
			row_end = maxf(row_end, button.get_global_rect().end.x)
		var list := scroll.get_global_rect()
		var bar := scroll.get_v_scroll_bar().size.x
		var left_gap := first.position.x - list.position.x
		var right_gap := list.end.x - bar - row_end
		assert_lt(left_gap, 8.0, "%s: the first card starts at the list's edge" % size)
		assert_lt(
			right_gap, 24.0, "%s: the row reaches its far side (%.0f left)" % [size, right_gap]
		)
		assert_gte(screen.cards()[0].size.x, LevelCard.CARD_SIZE.x, "%s: never narrower" % size)
		screen.free()
