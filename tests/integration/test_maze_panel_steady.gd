extends GutTest
## The side panel is the same on every board and stays put while playing (a play trial: a
## ~25 px joystick on First Roll, a large one on Switchbacks; the whole panel jumped 14 px
## when the medal line wrapped to two lines).

const TestMazeFraming := preload("res://tests/integration/test_maze_framing.gd")
const GAME := preload("res://scenes/maze/maze_game.tscn")
const TEST_SETTINGS := "user://test_maze_panel_steady_settings.cfg"
const TEST_SAVE := "user://test_maze_panel_steady_save.cfg"


func before_all() -> void:
	App.load_player_files(TEST_SETTINGS, TEST_SAVE)


func after_all() -> void:
	# the next test files expect the default board, as the other maze tests leave it
	App.request_board(BoardLevel.MAZE_NAME, "res://levels/maze/classic.board")
	App.load_player_files(App.SETTINGS_PATH, App.SAVE_PATH)
	for path in [TEST_SETTINGS, TEST_SAVE]:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(path))


# The game on `board` in a 1280 x 720 window, settled.
func _game(board: String) -> MazeGame:
	App.request_board(BoardLevel.MAZE_NAME, "res://levels/maze/%s.board" % board)
	var port := SubViewport.new()
	port.size = Vector2i(1280, 720)
	port.render_target_update_mode = SubViewport.UPDATE_DISABLED
	add_child_autofree(port)
	var game: MazeGame = GAME.instantiate()
	port.add_child(game)
	await wait_process_frames(4)
	game.lay_out()
	await wait_process_frames(1)
	return game


func test_the_joystick_is_one_size_on_every_shipped_board() -> void:
	var sizes: Array[String] = []
	var first := -1.0
	for board in TestMazeFraming.shipped_boards():
		var game: MazeGame = await _game(board)
		var stick := game.get_node("%Joystick") as MazeJoystick
		var drawn := MazeJoystick.drawn_size(stick.ui_scale)
		sizes.append("%s %.0f" % [board, drawn])
		if first < 0.0:
			first = drawn
		assert_almost_eq(drawn, first, 0.5, "%s: the joystick's size" % board)
		assert_gte(drawn, 140.0, "%s: big enough to grab" % board)
		game.queue_free()
	gut.p("joystick px at 1280x720: " + ", ".join(sizes))


func test_the_panel_stays_put_when_the_medal_line_wraps() -> void:
	var game: MazeGame = await _game("cloister")
	var stick := game.get_node("%Joystick") as Control
	var title := game.get_node("%Title") as Control
	var before := [stick.global_position, title.global_position]
	game.rules.start()
	game.rules.elapsed = 3600.0  # past every medal: the longer line
	game._process(0.0)
	await wait_process_frames(2)
	assert_ne(game.next_medal_text(), "", "a line about the medal")
	assert_eq([stick.global_position, title.global_position], before, "nothing moved")


# A play trial saw the panel drawn larger during "Loading…" (title and controls cut off),
# then shrink once the board was up: the joystick kept its designed double size until the
# first layout that fitted.
func test_the_panel_fits_from_the_first_frame() -> void:
	App.request_board(BoardLevel.MAZE_NAME, "res://levels/maze/first_roll.board")
	var port := SubViewport.new()
	port.size = Vector2i(1280, 720)
	port.render_target_update_mode = SubViewport.UPDATE_DISABLED
	add_child_autofree(port)
	var game: MazeGame = GAME.instantiate()
	port.add_child(game)
	var side := game.get_node("Side") as Control
	var stick := game.get_node("%Joystick") as MazeJoystick
	assert_lte(
		MazeJoystick.drawn_size(stick.ui_scale),
		MazeJoystick.drawn_size(MazePanelLayout.JOYSTICK_SCALE) + 0.5,
		"the joystick at its size at once"
	)
	await wait_process_frames(1)  # the column has its width: its lines wrap to it
	assert_lte(side.get_combined_minimum_size().y, 720.0, "the panel fits the window at once")
