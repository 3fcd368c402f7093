extends GutTest
## Keyboard and gamepad focus is visible on the maze screen: every button there (the win
## card's Next board / Retry / Menu, the side panel's Calibrate) draws a thick ring that
## stands out from the light panel behind it.

const GAME := preload("res://scenes/maze/maze_game.tscn")
const TEST_SETTINGS := "user://test_maze_focus_settings.cfg"
const TEST_SAVE := "user://test_maze_focus_save.cfg"


func before_all() -> void:
	App.load_player_files(TEST_SETTINGS, TEST_SAVE)


func after_all() -> void:
	App.load_player_files(App.SETTINGS_PATH, App.SAVE_PATH)
	for path in [TEST_SETTINGS, TEST_SAVE]:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(path))


# A keyboard or gamepad player sees which button has the focus: Godot's default ring was a
# faint white line, invisible on the light win card and side panel.
func test_every_maze_button_shows_a_focus_ring_that_stands_out() -> void:
	var game: MazeGame = GAME.instantiate()
	add_child_autofree(game)
	var card := MazeWinPanel.CARD
	var buttons: Array[Button] = game.win_panel().buttons()
	buttons.append(game.get_node("%Calibrate"))
	for button in buttons:
		var ring := button.get_theme_stylebox("focus") as StyleBoxFlat
		assert_not_null(ring, "%s: a drawn focus ring" % button.text)
		if ring == null:
			continue
		assert_false(ring.draw_center, "%s: a ring, not a fill over the text" % button.text)
		assert_gte(ring.border_width_top, 2, "%s: thick enough to see" % button.text)
		assert_gte(ring.border_color.a, 0.9, button.text)
		var contrast := MazeFocusRing.contrast(ring.border_color, card)
		assert_gte(contrast, 3.0, "%s: ring against the card %.1f : 1" % [button.text, contrast])


# A play trial held the arrow key that rolled the last ball in: its repeats walked the focus
# from Next board to Menu, and Enter went back to the menu. The card ignores the arrow and
# accept keys for its first moments, then they move the focus as usual.
func test_an_arrow_key_held_as_the_card_appears_leaves_next_board_focused() -> void:
	var game: MazeGame = GAME.instantiate()
	add_child_autofree(game)
	var panel := game.win_panel()
	panel.present(MazeWinSummary.new(), false, true)
	await wait_process_frames(2)
	var next := panel.buttons()[0]
	assert_true(next.has_focus(), "Next board takes the focus")
	for i in 3:
		Input.parse_input_event(_right_key())
		await wait_process_frames(1)
	assert_true(next.has_focus(), "a held arrow key does not walk the focus away")
	await wait_seconds(MazeWinPanel.HELD_KEYS_IGNORED_MSEC / 1000.0 + 0.1)
	Input.parse_input_event(_right_key())
	await wait_process_frames(2)
	assert_false(next.has_focus(), "later the arrow keys move the focus as usual")


func _right_key() -> InputEventKey:
	var key := InputEventKey.new()
	key.keycode = KEY_RIGHT
	key.physical_keycode = KEY_RIGHT
	key.pressed = true
	return key
