extends GutTest
## The fine key shows (trial 10: "I never saw Shift fine tilt make a noticeable difference"):
## while it is held the joystick says FINE and rings the head's reach at half tilt, and its
## tap rolls a ball about half as far as a plain one.

const GAME := preload("res://scenes/maze/maze_game.tscn")
const MazeTaps := preload("res://tests/helpers/maze_taps.gd")
const TEST_SETTINGS := "user://test_maze_fine_settings.cfg"
const TEST_SAVE := "user://test_maze_fine_save.cfg"


func before_all() -> void:
	App.load_player_files(TEST_SETTINGS, TEST_SAVE)


func after_all() -> void:
	App.load_player_files(App.SETTINGS_PATH, App.SAVE_PATH)
	for path in [TEST_SETTINGS, TEST_SAVE]:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(path))


func after_each() -> void:
	Input.action_release("tilt_fine")


func test_the_joystick_says_fine_while_the_key_is_held() -> void:
	var game: MazeGame = GAME.instantiate()
	add_child_autofree(game)
	await wait_process_frames(2)
	var joystick: MazeJoystick = game.get_node("%Joystick")
	var label := joystick.fine_label()
	assert_not_null(label, "the joystick has a fine label")
	if label == null:
		return
	assert_false(label.is_visible_in_tree(), "hidden with the key up")
	Input.action_press("tilt_fine")
	await wait_process_frames(2)
	assert_true(joystick.fine, "the joystick knows")
	assert_true(label.is_visible_in_tree(), "shown with the key down")
	assert_eq(label.text, "FINE")
	Input.action_release("tilt_fine")
	await wait_process_frames(2)
	assert_false(label.is_visible_in_tree(), "hidden again once it is let go")


func test_a_fine_tap_rolls_about_half_as_far() -> void:
	var tap := MazeTaps.travel(0.1, 60.0)
	var fine := MazeTaps.travel(0.1, 60.0, [0.0], true)
	gut.p("tap %.1f px, fine tap %.1f px" % [tap, fine])
	assert_between(fine, 0.4 * tap, 0.65 * tap, "about half")
