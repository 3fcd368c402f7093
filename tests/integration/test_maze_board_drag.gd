extends GutTest
## Trial 9: "the mouse joystick allows partial tilt, but it is small and sits far from the
## board"; and a tap's tilt depended on how long the key was seen held. A drag that starts on
## the board tilts it as the joystick does, and a tilt key's press event nudges the board even
## when no frame sees the key held.

const GAME := preload("res://scenes/maze/maze_game.tscn")
const TEST_SETTINGS := "user://test_maze_board_drag_settings.cfg"
const TEST_SAVE := "user://test_maze_board_drag_save.cfg"


func before_all() -> void:
	App.load_player_files(TEST_SETTINGS, TEST_SAVE)


func after_all() -> void:
	App.load_player_files(App.SETTINGS_PATH, App.SAVE_PATH)
	for path in [TEST_SETTINGS, TEST_SAVE]:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(path))


# The game screen in a 1280 x 720 window of its own, laid out.
func _game() -> MazeGame:
	var port := SubViewport.new()
	port.size = Vector2i(1280, 720)
	port.render_target_update_mode = SubViewport.UPDATE_DISABLED
	add_child_autofree(port)
	var game: MazeGame = GAME.instantiate()
	port.add_child(game)
	await wait_process_frames(2)
	return game


func _mouse_button(at: Vector2, down: bool) -> InputEventMouseButton:
	var event := InputEventMouseButton.new()
	event.button_index = MOUSE_BUTTON_LEFT
	event.pressed = down
	event.position = at
	event.global_position = at
	return event


func _mouse_move(at: Vector2) -> InputEventMouseMotion:
	var event := InputEventMouseMotion.new()
	event.position = at
	event.global_position = at
	return event


func test_a_drag_on_the_board_tilts_it_as_the_joystick_does() -> void:
	var game: MazeGame = await _game()
	var region := game.lay_out()
	var centre := region.get_center()
	var full := minf(region.size.x, region.size.y) * MazeBoardDrag.FULL_DRAG_SHARE
	game.get_viewport().push_input(_mouse_button(centre, true))
	await wait_process_frames(1)
	assert_eq(game.rules.state, MazeRules.State.PLAYING, "a press on the board starts the run")
	assert_eq(game.mixer.tilt, Vector2.ZERO, "a click without a drag leaves the board level")
	game.get_viewport().push_input(_mouse_move(centre + Vector2(full * 0.05, 0.0)))
	assert_eq(game.mixer.tilt, Vector2.ZERO, "the joystick's dead zone")
	game.get_viewport().push_input(_mouse_move(centre + Vector2(full * 0.5, 0.0)))
	var half := TiltInput.tilt_from_joystick(Vector2(TiltInput.JOYSTICK_RANGE * 0.5, 0.0))
	assert_almost_eq(game.mixer.tilt.x, half.x, 0.01, "half way: the joystick's gentle curve")
	game.get_viewport().push_input(_mouse_move(centre + Vector2(0.0, -full * 2.0)))
	assert_almost_eq(game.mixer.tilt.y, -TiltInput.MAX_TILT_DEG, 0.01, "far up: full tilt up")
	game.get_viewport().push_input(_mouse_button(centre + Vector2(0.0, -full * 2.0), false))
	assert_eq(game.mixer.tilt, Vector2.ZERO, "let go: level")


func test_a_press_beside_the_board_is_no_drag() -> void:
	var game: MazeGame = await _game()
	var region := game.lay_out()
	game.get_viewport().push_input(_mouse_button(region.position - Vector2(5.0, 5.0), true))
	game.get_viewport().push_input(_mouse_move(region.position + Vector2(60.0, 60.0)))
	assert_eq(game.rules.state, MazeRules.State.READY, "the run has not started")
	assert_eq(game.mixer.tilt, Vector2.ZERO)
	game.get_viewport().push_input(_mouse_button(region.position, false))


func test_a_key_pressed_and_let_go_inside_one_frame_nudges_the_board() -> void:
	var game: MazeGame = await _game()
	var press := InputEventAction.new()
	press.action = &"tilt_right"
	press.pressed = true
	game._unhandled_input(press)  # the key is up again before the frame reads the keys
	assert_eq(game.rules.state, MazeRules.State.PLAYING, "the press starts the run")
	await wait_seconds(0.05)  # within the nudge's 0.12 s
	assert_gt(game.rules.tilt.x, 0.0, "the board leans right though no frame saw the key held")
