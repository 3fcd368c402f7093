extends GutTest
## The maze screen headless: the board is a SubViewport texture on a quad that tilts in 3D,
## the joystick starts and tilts, keys tilt smoothly, Space / H / E reset and switch, and a
## win shows the seed's message and saves the best time.

const GAME := preload("res://scenes/maze/maze_game.tscn")
const TEST_SETTINGS := "user://test_maze_settings.cfg"
const TEST_SAVE := "user://test_maze_save.cfg"

var _game: Control


func before_all() -> void:
	App.load_player_files(TEST_SETTINGS, TEST_SAVE)
	ReplayStore.folder = "user://test_maze_scene_replays"


func after_all() -> void:
	App.load_player_files(App.SETTINGS_PATH, App.SAVE_PATH)
	ReplayStore.folder = ReplayStore.DIR
	var replays := "user://test_maze_scene_replays"
	for file_name in DirAccess.get_files_at(replays):
		DirAccess.remove_absolute(ProjectSettings.globalize_path(replays + "/" + file_name))
	DirAccess.remove_absolute(ProjectSettings.globalize_path(replays))
	for path in [TEST_SETTINGS, TEST_SAVE]:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(path))


func before_each() -> void:
	_game = GAME.instantiate()
	add_child_autofree(_game)


func after_each() -> void:
	Input.action_release("tilt_right")


func _rules() -> MazeRules:
	return _game.get("rules")


func _note() -> String:
	return str(_game.get_node("%Note").call("text"))


func _press(action: String) -> void:
	var event := InputEventAction.new()
	event.action = action
	event.pressed = true
	_game.call("_unhandled_input", event)


func test_the_board_is_a_viewport_texture_on_a_quad_seen_in_perspective() -> void:
	var rules := _rules()
	assert_not_null(rules, "the classic board loaded")
	var canvas: SubViewport = _game.get_node("BoardCanvas")
	assert_eq(Vector2(canvas.size), rules.level.size * 3.0, "drawn at 3 texture px per board px")
	var stage: Node3D = _game.get_node("Stage")
	var camera: Camera3D = stage.call("camera")
	assert_eq(camera.projection, Camera3D.PROJECTION_PERSPECTIVE)
	var quads := stage.find_children("*", "MeshInstance3D", true, false)
	var textured := false
	for node in quads:
		var mat := (node as MeshInstance3D).material_override as StandardMaterial3D
		if mat != null and mat.albedo_texture == canvas.get_texture():
			textured = true
	assert_true(textured, "a 3D quad shows the board's SubViewport")


func test_the_joystick_starts_the_game_and_tilts_the_board() -> void:
	var joystick: Control = _game.get_node("%Joystick")
	assert_true(joystick.get("glowing"), "the head glows until first used")
	joystick.emit_signal("pressed")
	_game.call("_start")
	assert_true(_rules().is_playing())
	joystick.emit_signal("moved", Vector2(40.0, -7.5))
	_game.call("_process", 0.016)
	assert_eq(_rules().tilt, Vector2(12.0, -6.0), "15 px max travel, 0.8° per px")
	var shown: Vector2 = _game.get_node("Stage").call("shown_tilt")
	assert_almost_eq(shown.x, 12.0, 0.01, "the 3D board turns with the tilt")
	assert_almost_eq(shown.y, -6.0, 0.01)


func test_the_head_is_clamped_to_fifteen_pixels() -> void:
	var joystick: Control = _game.get_node("%Joystick")
	joystick.set("head_offset", Vector2(-99.0, 40.0))
	assert_eq(joystick.get("head_offset"), Vector2(-15.0, 15.0))


func test_keys_tilt_smoothly_not_at_once() -> void:
	Input.action_press("tilt_right")
	_game.call("_process", 1.0 / 60.0)
	assert_true(_rules().is_playing(), "a tilt key starts the game too")
	_game.call("_process", 1.0 / 60.0)
	var early := _rules().tilt.x
	assert_between(early, 0.1, 6.0, "eases toward the target")
	for i in 60:
		_game.call("_process", 1.0 / 60.0)
	assert_almost_eq(_rules().tilt.x, 12.0, 0.2, "reaches full tilt within a second")


func test_space_h_and_e_reset_and_switch_modes() -> void:
	_game.call("_start")
	_rules().set_tilt(Vector2(12.0, 12.0))
	_rules().advance(0.5)
	_press("maze_hard_mode")
	assert_true(_rules().hard_mode)
	assert_eq(_rules().state, MazeRules.State.READY)
	assert_string_contains(_note(), "avoid the black holes")
	assert_eq(str(_game.get_node("%Mode").text), "HARD MODE")
	_game.call("_start")
	_rules().set_tilt(Vector2(0.0, 12.0))
	_rules().advance(0.5)
	_press("maze_reset")
	assert_true(_rules().hard_mode, "Space keeps the mode")
	assert_eq(_rules().ball_positions(), _rules().level.ball_starts)
	_press("maze_easy_mode")
	assert_false(_rules().hard_mode)
	assert_string_contains(_note(), "Ready for hard mode? Press H")


func test_a_win_shows_the_message_and_saves_the_best_time() -> void:
	var rules := _rules()
	_game.call("_start")
	rules.set_tilt(Vector2(3.0, 0.0))
	rules.advance(0.25)
	var ids := rules.world.get_ids()
	for i in ids.size():
		rules.world.set_ball_position(ids[i], rules.level.goal_center + Vector2(i * 10 - 15, 0))
	rules.step()
	assert_eq(rules.state, MazeRules.State.WON)
	assert_string_contains(_note(), "Congrats, you did it!")
	assert_string_contains(_note(), "Press H for hard mode")
	var best := App.best_maze_time(rules.level.board_id, false)
	assert_almost_eq(best, rules.elapsed, 0.001, "the time is saved as the best")


func test_a_loss_names_the_reset_key() -> void:
	var rules := _rules()
	_press("maze_hard_mode")
	_game.call("_start")
	var id := rules.world.get_ids()[0]
	rules.world.set_ball_position(id, rules.level.holes[1] + Vector2(-12.0, 0.0))
	rules.world.set_ball_velocity(id, Vector2(60.0, 0.0))
	for i in 30:
		rules.step()
	assert_eq(rules.state, MazeRules.State.LOST)
	assert_string_contains(_note(), "A ball fell into a black hole! Press Space to reset")
