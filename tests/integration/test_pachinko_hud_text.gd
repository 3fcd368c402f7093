extends GutTest
## The pachinko side panel reads on a phone: the project draws its 1280 × 720 design at 0.56
## on a 720 × 1280 screen, which made the launcher's hint and HANDLE 7 px and the notes 8 px
## in a 420-wide band under the board. Now the panel in that band puts the cup beside the
## numbers and the launcher under them, and is drawn bigger: every word of it is at least
## 14 px on the screen at 720 × 1280, and the launcher, drawn bigger still, fills the band's
## height (it stood beside the numbers and left the band's last 197 px empty). At
## 1280 × 720 and 900 × 700 it is the column beside the board; a 900 × 700
## window drew it at 0.7 (the launcher's words 9.8 px), so there the column is drawn bigger
## and wider by as much, and every word reads at 14 px in all three windows. In every
## window the panel stays on screen, off the board, and its content fits it.

const GAME := preload("res://scenes/pachinko/pachinko_game.tscn")
const StretchedWindow := preload("res://tests/integration/stretched_window.gd")
const SIZES: Array[Vector2i] = [Vector2i(720, 1280), Vector2i(900, 700), Vector2i(1280, 720)]


func before_each() -> void:
	App.request_board("pachinko", "res://levels/pachinko/classic.board")


## The game in a window of `size` stretched as the project stretches its own window.
func _game_in_window(size: Vector2i) -> PachinkoGame:
	return await StretchedWindow.open(self, GAME, size, 4) as PachinkoGame


## Every text of the panel with the font size it is drawn at: its labels, the numbers, the
## cup's words and the launcher's.
static func _panel_texts(game: PachinkoGame) -> Dictionary:
	var sizes := {}
	for label: Label in [game.title, game.notes]:
		sizes[label.name] = (
			MazeSideText.font_size_of(label) * StretchedWindow.px_per_font_unit(label)
		)
	var numbers := game.stats_panel.find_children("*", "RichTextLabel", true, false)
	var rich := numbers[0] as RichTextLabel
	sizes["Stats"] = (
		rich.get_theme_font_size(&"normal_font_size") * StretchedWindow.px_per_font_unit(rich)
	)
	sizes["Cup"] = CupDisplay.LABEL_FONT_SIZE * StretchedWindow.px_per_font_unit(game.cup)
	sizes["Launcher"] = (
		LauncherPanel.SMALL_FONT_SIZE * StretchedWindow.px_per_font_unit(game.launcher)
	)
	return sizes


func test_every_word_of_the_panel_reads_at_14_px() -> void:
	for size in SIZES:
		var game := await _game_in_window(size)
		var sizes := _panel_texts(game)
		assert_eq(sizes.size(), 5)
		for text: String in sizes:
			assert_gte(sizes[text], 14.0, "%s: the %s is %.1f px" % [size, text, sizes[text]])
		game.free()  # before its window


func test_a_phone_puts_the_panel_under_the_board() -> void:
	var game := await _game_in_window(Vector2i(720, 1280))
	# QA: its gold edge stayed on the left, a stray line down the screen's edge under the board
	var style := game.hud.get_theme_stylebox(&"panel") as StyleBoxFlat
	assert_gt(style.border_width_top, 0, "the panel's edge runs along the board above it")
	assert_eq(style.border_width_left, 0, "not down the screen's left edge")
	game.free()  # before its window, whose last size change it would answer


func test_landscape_keeps_the_designed_column_beside_the_board() -> void:
	for size: Vector2i in [Vector2i(1280, 720), Vector2i(900, 700)]:
		var game := await _game_in_window(size)
		var stretch := game.get_viewport().get_final_transform().get_scale().y
		var zoom := maxf(1.0, 14.0 / (LauncherPanel.SMALL_FONT_SIZE * stretch))
		assert_almost_eq(game.hud.scale.x, zoom, 0.011, "%s: drawn big enough to read" % size)
		assert_true(game.hud_column.vertical, "%s: one column" % size)
		var style := game.hud.get_theme_stylebox(&"panel") as StyleBoxFlat
		assert_gt(style.border_width_left, 0, "%s: its edge along the board" % size)
		assert_eq(style.border_width_top, 0)
		var view := game.get_viewport_rect().size
		assert_almost_eq(game.hud.size.x, PachinkoGame.HUD_WIDTH, 0.5, "the designed column")
		assert_almost_eq(game.hud.get_global_rect().end.x, view.x, 0.5, "on the right edge")
		assert_almost_eq(game.hud.get_global_rect().size.y, view.y, 0.5, "top to bottom")
		game.free()


func test_the_panel_stays_on_screen_off_the_board_and_holds_its_content() -> void:
	for size in SIZES:
		var game := await _game_in_window(size)
		var view := game.get_viewport_rect()
		var panel := game.hud.get_global_rect()
		var board := game.instructions.get_global_rect()  # laid over the board's area
		assert_true(view.grow(0.5).encloses(panel), "%s: the panel %s is on screen" % [size, panel])
		assert_false(panel.intersects(board), "%s: the panel %s is off the board" % [size, panel])
		var needed := game.hud_column.get_combined_minimum_size()
		assert_lte(needed.x, game.hud_column.size.x + 0.5, "%s: its content fits across" % size)
		assert_lte(needed.y, game.hud_column.size.y + 0.5, "%s: and down" % size)
		game.free()


## Where the panel's drawn content ends, in view units: its words' rects and the launcher's
## drawing (its minimum size: the room it is drawn in).
static func _lowest_drawn(game: PachinkoGame) -> float:
	var lowest := 0.0
	for control: Control in [game.title, game.cup, game.stats_panel, game.notes]:
		lowest = maxf(lowest, control.get_global_rect().end.y)
	var launcher := game.launcher
	var drawn := (
		launcher.get_combined_minimum_size().y * launcher.get_global_transform().get_scale().y
	)
	return maxf(lowest, launcher.get_global_position().y + drawn)


func test_a_phone_leaves_no_empty_band_under_the_panel() -> void:
	# QA: the numbers and the launcher sat side by side in the band's top, and its last
	# 197 px stayed empty at 720 × 1280
	var game := await _game_in_window(Vector2i(720, 1280))
	var view := game.get_viewport_rect().size
	var stretch := game.get_viewport().get_final_transform().get_scale().y
	var empty_px := (view.y - _lowest_drawn(game)) * stretch
	assert_lte(empty_px, 24.0, "%.0f px under the panel's content" % empty_px)
	var launcher := game.launcher
	assert_gt(launcher.art_scale(), 1.1, "the launcher takes the height: drawn bigger")
	var drawn := Rect2(
		launcher.get_global_position(), launcher.size * launcher.scale * game.hud.scale
	)
	for control: Control in [game.title, game.cup, game.stats_panel, game.notes]:
		assert_false(drawn.intersects(control.get_global_rect()), "not over the %s" % control.name)
	assert_true(Rect2(Vector2.ZERO, view).grow(0.5).encloses(drawn), "on screen: %s" % drawn)
	# a press lands where it is drawn
	var dial: Vector2 = LauncherPanel.DIAL_CENTER * launcher.art_scale()
	assert_true(launcher.is_on_handle(dial), "the dial drawn bigger is pressed where it shows")
	assert_false(launcher.is_on_handle(LauncherPanel.DIAL_CENTER + Vector2(0, 60)))
	game.free()


func test_landscape_draws_the_launcher_at_its_design_size() -> void:
	for size: Vector2i in [Vector2i(1280, 720), Vector2i(900, 700)]:
		var game := await _game_in_window(size)
		assert_eq(game.launcher.art_scale(), 1.0, "%s" % size)
		assert_eq(game.launcher.get_combined_minimum_size(), LauncherPanel.DESIGN_SIZE)
		game.free()
