extends GutTest
## The keys on the maze's finish card: an arrow key held from play as the last ball rolls in
## leaves Next board focused (it is ignored until let go), and H on the card starts the
## board again in hard mode, as the side panel's "Press H for hard mode" says.

const GAME := preload("res://scenes/maze/maze_game.tscn")
const TEST_SETTINGS := "user://test_maze_win_card_keys_settings.cfg"
const TEST_SAVE := "user://test_maze_win_card_keys_save.cfg"
const REPLAYS := "user://test_maze_win_card_keys_replays"

var _game: MazeGame
var _kept_save: SaveData


func before_all() -> void:
	App.load_player_files(TEST_SETTINGS, TEST_SAVE)
	ReplayStore.folder = REPLAYS


func after_all() -> void:
	App.load_player_files(App.SETTINGS_PATH, App.SAVE_PATH)
	ReplayStore.folder = ReplayStore.DIR
	for file_name in DirAccess.get_files_at(REPLAYS):
		DirAccess.remove_absolute(ProjectSettings.globalize_path(REPLAYS + "/" + file_name))
	DirAccess.remove_absolute(ProjectSettings.globalize_path(REPLAYS))
	for path in [TEST_SETTINGS, TEST_SAVE]:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(path))


func before_each() -> void:
	_kept_save = App.save_data
	App.save_data = SaveData.new()  # in memory only: never written
	_game = GAME.instantiate()
	add_child_autofree(_game)
	await wait_process_frames(1)


func after_each() -> void:
	for keycode: Key in [KEY_RIGHT, KEY_H]:
		Input.parse_input_event(_key(keycode, false))
	App.save_data = _kept_save


# Rolls every ball into the dip: the board is won and the card is up.
func _win() -> void:
	var rules := _game.rules
	_game._start()
	var ids := rules.world.get_ids()
	for i in ids.size():
		rules.world.set_ball_position(ids[i], rules.level.goal_center + Vector2(i * 10 - 15, 0))
	rules.step()


func _key(keycode: Key, pressed: bool, echo := false) -> InputEventKey:
	var key := InputEventKey.new()
	key.keycode = keycode
	key.physical_keycode = keycode
	key.pressed = pressed
	key.echo = echo
	return key


# A play trial held Right as the last ball rolled in: the key's repeats went on after the
# card's first moments, walked the focus from Next board to Menu, and Enter went to the list.
func test_an_arrow_key_held_from_play_never_walks_the_focus() -> void:
	Input.parse_input_event(_key(KEY_RIGHT, true))
	await wait_process_frames(2)
	_win()
	var panel := _game.win_panel()
	assert_true(panel.visible, "the card is up")
	await wait_process_frames(2)
	var next := panel.buttons()[0]
	assert_true(next.has_focus(), "Next board takes the focus")
	await wait_seconds(MazeWinPanel.HELD_KEYS_IGNORED_MSEC / 1000.0 + 0.1)
	for i in 4:
		Input.parse_input_event(_key(KEY_RIGHT, true, true))
		await wait_process_frames(1)
	assert_true(next.has_focus(), "the held key's repeats, even late, leave Next board focused")
	Input.parse_input_event(_key(KEY_RIGHT, false))
	await wait_process_frames(1)
	Input.parse_input_event(_key(KEY_RIGHT, true))
	await wait_process_frames(2)
	assert_false(next.has_focus(), "let go and pressed again, Right moves the focus")


# The side panel says "Press H for hard mode" while the card is up: H there starts the board
# again in hard mode.
func test_h_on_the_card_starts_the_board_again_in_hard_mode() -> void:
	_win()
	var panel := _game.win_panel()
	await wait_process_frames(2)
	assert_true(panel.buttons()[0].has_focus(), "the card has the focus")
	assert_false(_game.rules.hard_mode)
	Input.parse_input_event(_key(KEY_H, true))
	await wait_process_frames(2)
	assert_true(_game.rules.hard_mode, "H switched to hard mode")
	assert_eq(_game.rules.state, MazeRules.State.READY, "the board is ready to play again")
	assert_false(panel.visible, "and the card is gone")


# Trial 9: the first finish's card focused Menu, later ones Next board. At 3 to 37 FPS the taps
# meant for the last ball landed after the card's 600 ms, with the card drawn a frame or two:
# the card ignores the menu keys for its first frames too, so Next board keeps the focus.
func test_taps_after_600_ms_on_a_slow_machine_leave_next_board_focused() -> void:
	_win()
	var panel := _game.win_panel()
	await wait_process_frames(1)  # the focus is given
	var next := panel.buttons()[0]
	assert_true(next.has_focus(), "Next board takes the focus")
	OS.delay_msec(MazeWinPanel.HELD_KEYS_IGNORED_MSEC + 100)  # one long frame
	for i in 2:
		Input.parse_input_event(_key(KEY_RIGHT, true))
		Input.parse_input_event(_key(KEY_RIGHT, false))
		await wait_process_frames(1)
	assert_true(next.has_focus(), "two quick Right taps leave Next board focused")
	await wait_process_frames(MazeWinPanel.HELD_KEYS_IGNORED_FRAMES)
	Input.parse_input_event(_key(KEY_RIGHT, true))
	Input.parse_input_event(_key(KEY_RIGHT, false))
	await wait_process_frames(2)
	assert_false(next.has_focus(), "later Right moves the focus as usual")
