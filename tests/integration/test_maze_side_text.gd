extends GutTest
## The maze side panel's text is readable on the screen: a portrait phone draws the
## 1280 × 720 design at 0.56 (the project's canvas_items stretch), which made the hint about
## 10 px tall, and a 900 × 700 window draws it at 0.7 (the controls line 10.5 px); now every
## label and button of the panel is at least 14 px on the screen at 720 × 1280, 900 × 700
## and 1280 × 720 (a small window's column widens with its text), and the panel still
## keeps off the board and on screen.

const GAME := preload("res://scenes/maze/maze_game.tscn")
const StretchedWindow := preload("res://tests/integration/stretched_window.gd")
const SIZES: Array[Vector2i] = [Vector2i(720, 1280), Vector2i(1280, 720), Vector2i(900, 700)]


## The game in a window of `size` stretched as the project stretches its own window.
func _game_in_window(size: Vector2i) -> MazeGame:
	return await StretchedWindow.open(self, GAME, size, 3) as MazeGame


func test_the_side_text_is_at_least_14_px_on_screen() -> void:
	for size in SIZES:
		var game := await _game_in_window(size)
		var scale := game.get_viewport().get_final_transform().get_scale().y
		var side: Control = game.get_node("Side")
		var hint: Label = game.get_node("Side/Note/Hint")
		var on_screen := MazeSideText.font_size_of(hint) * scale
		assert_gte(on_screen, 14.0, "%s: the hint is %.1f px" % [size, on_screen])
		var checked := 0
		for node in side.find_children("*", "Control", true, false):
			if node is Label or node is Button:
				checked += 1
				var px := MazeSideText.font_size_of(node as Control) * scale
				assert_gte(px, 14.0, "%s: %s is %.1f px" % [size, node.name, px])
		assert_gte(checked, 9, "every label and the button were looked at")
		game.free()  # before its window, whose last size change it would answer


func test_the_grown_text_keeps_off_the_board_and_on_screen() -> void:
	for size in SIZES:
		var game := await _game_in_window(size)
		var region: Rect2 = game.lay_out()
		await wait_process_frames(2)
		var view := game.get_viewport_rect()
		var side: Control = game.get_node("Side")
		var rect := side.get_global_rect()
		assert_false(rect.intersects(region), "%s: the panel %s is off the board" % [size, rect])
		assert_true(view.encloses(rect.grow(-1.0)), "%s: the panel %s is on screen" % [size, rect])
		var needed := side.get_combined_minimum_size()
		assert_lte(needed.y, rect.size.y + 0.5, "%s: the panel's content fits its band" % size)
		assert_lte(needed.x, rect.size.x + 0.5, "%s: and its column" % size)
		game.free()


func test_the_win_card_reads_at_14_px_and_stays_over_the_board() -> void:
	for size: Vector2i in [Vector2i(720, 1280), Vector2i(900, 700), Vector2i(1280, 720)]:
		var game := await _game_in_window(size)
		var region: Rect2 = game.lay_out()
		var panel := game.win_panel()
		var summary := MazeWinSummary.new()
		summary.seconds = 49.1
		panel.present(summary, false, true)
		await wait_process_frames(3)
		var scale := game.get_viewport().get_final_transform().get_scale().y
		var checked := 0
		for node in panel.find_children("*", "Control", true, false):
			if node is Label or node is Button:
				checked += 1
				var px := MazeSideText.font_size_of(node as Control) * scale
				assert_gte(px, 14.0, "%s: the win card's %s is %.1f px" % [size, node.name, px])
		assert_eq(checked, 7, "four lines and three buttons")
		var card: Control = panel.get_child(0)
		assert_true(
			region.grow(0.5).encloses(card.get_global_rect()),
			"%s: the card %s stays over the board %s" % [size, card.get_global_rect(), region]
		)
		game.free()


# A play trial resized the window to 900 x 700 and back: the joystick stayed small and the
# panel kept the small window's spacing.
func test_a_window_resized_small_and_back_gets_its_layout_back() -> void:
	var game := await _game_in_window(Vector2i(1280, 720))
	var stick: MazeJoystick = game.get_node("%Joystick")
	var first_scale := stick.ui_scale
	var window := game.get_window()
	window.size = Vector2i(900, 700)
	await wait_process_frames(4)
	window.size = Vector2i(1280, 720)
	await wait_process_frames(4)
	assert_almost_eq(
		stick.ui_scale, first_scale, 0.05, "the joystick is its size again (was 0.78 of 1.59)"
	)
	game.free()
