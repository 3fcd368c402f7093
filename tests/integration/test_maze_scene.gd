extends GutTest
## The maze screen headless: the board is built in 3D from the level (raised walls, frame,
## holes in hard mode, rolling balls, a fixed sun), no tilt sinks it through the table, the
## joystick starts and tilts, keys tilt smoothly, Space / R / Back / H / E reset and switch,
## and a win shows the seed's message and saves the best time.

const GAME := preload("res://scenes/maze/maze_game.tscn")
const TEST_SETTINGS := "user://test_maze_settings.cfg"
const TEST_SAVE := "user://test_maze_save.cfg"

var _game: MazeGame


func before_all() -> void:
	App.load_player_files(TEST_SETTINGS, TEST_SAVE)
	ReplayStore.folder = "user://test_maze_scene_replays"


func after_all() -> void:
	App.maze_hard_chosen = false  # H here is the player's choice for the next board
	App.load_player_files(App.SETTINGS_PATH, App.SAVE_PATH)
	ReplayStore.folder = ReplayStore.DIR
	var replays := "user://test_maze_scene_replays"
	for file_name in DirAccess.get_files_at(replays):
		DirAccess.remove_absolute(ProjectSettings.globalize_path(replays + "/" + file_name))
	DirAccess.remove_absolute(ProjectSettings.globalize_path(replays))
	for path in [TEST_SETTINGS, TEST_SAVE]:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(path))


func before_each() -> void:
	App.maze_hard_chosen = false  # H here is the player's choice for the next board
	_game = GAME.instantiate()
	add_child_autofree(_game)


func after_each() -> void:
	Input.action_release("tilt_right")


func _rules() -> MazeRules:
	return _game.rules


func _note() -> String:
	return str(_game.get_node("%Note").text())


func _press(action: String) -> void:
	var event := InputEventAction.new()
	event.action = action
	event.pressed = true
	_game._unhandled_input(event)


func _stage() -> MazeStage:
	return _game.get_node("Stage")


func test_the_board_is_built_in_3d_from_the_level() -> void:
	var rules := _rules()
	assert_not_null(rules, "the classic board loaded")
	var stage := _stage()
	var camera: Camera3D = stage.camera()
	# a perspective view, its frustum shifted to seat the board in its region
	assert_eq(camera.projection, Camera3D.PROJECTION_FRUSTUM)
	var board := stage.board()
	var walls: MeshInstance3D = board.part("walls")
	assert_not_null(walls.mesh, "the walls are a mesh")
	var wall_box := walls.mesh.get_aabb()
	var height: float = board.wall_height_px()
	assert_almost_eq(wall_box.end.z, height * 0.01, 0.0001, "walls stand up from the floor")
	assert_almost_eq(wall_box.position.z, 0.0, 0.0001, "and start on it")
	assert_gt(height, rules.level.ball_radius * 2.0, "higher than a ball")
	# walls reach the level's outermost wall ends, caps included
	var half_wall := rules.level.wall_width * 0.5
	var x_min := INF
	for p in rules.level.walls:
		x_min = minf(x_min, p.x)
	assert_almost_eq(
		wall_box.position.x, (x_min - half_wall - rules.level.size.x * 0.5) * 0.01, 0.002
	)
	var frame: MeshInstance3D = board.part("frame")
	assert_gt(frame.mesh.get_aabb().end.z, wall_box.end.z, "the frame stands above the walls")
	var floor_part: MeshInstance3D = board.part("floor")
	assert_true(floor_part.material_override is ShaderMaterial, "the floor paints goal and holes")
	var holes: MeshInstance3D = board.part("holes")
	assert_null(holes.mesh, "easy mode: no holes")


func test_hard_mode_sinks_the_holes_into_the_floor() -> void:
	_press("maze_hard_mode")
	var board := _stage().board()
	var holes: MeshInstance3D = board.part("holes")
	assert_not_null(holes.mesh, "hard mode: holes")
	var box := holes.mesh.get_aabb()
	assert_lt(box.position.z, -0.05, "the holes go down into the board")
	var floor_mat: ShaderMaterial = (board.part("floor") as MeshInstance3D).material_override
	assert_eq(floor_mat.get_shader_parameter("hole_count"), _rules().level.holes.size())
	_press("maze_easy_mode")
	assert_null(holes.mesh, "back to easy: the holes close")
	assert_eq(floor_mat.get_shader_parameter("hole_count"), 0)


func test_balls_are_lit_spheres_that_roll_with_their_motion() -> void:
	var rules := _rules()
	_game._process(0.016)
	var balls := _stage().balls()
	assert_eq(balls.shown_count(), rules.ball_total(), "one sphere per ball")
	var id := rules.world.get_ids()[0]
	var node: MeshInstance3D = balls.node_for(id)
	assert_true(node.mesh is SphereMesh)
	var mat := node.material_override as StandardMaterial3D
	assert_ne(mat.shading_mode, BaseMaterial3D.SHADING_MODE_UNSHADED, "lit by the sun")
	var before := node.basis
	_game._start()
	rules.world.set_ball_position(id, rules.world.get_ball_position(id) + Vector2(4.0, 0.0))
	_game._process(0.0)
	assert_false(node.basis.is_equal_approx(before), "moving turned the ball")
	var expected := rules.world.get_ball_position(id)
	var local := Vector3(expected.x - 175.0, 157.5 - expected.y, rules.level.ball_radius) * 0.01
	assert_almost_eq(node.position.distance_to(local), 0.0, 0.0001, "it sits on the floor")


func test_the_sun_stays_put_and_its_shadows_follow_the_tilt() -> void:
	var stage := _stage()
	var sun: DirectionalLight3D = stage.sun()
	var board := stage.board()
	var floor_material := board.floor_material()
	assert_false(sun.shadow_enabled, "the floor lays its own soft shadows, not a shadow map")
	var before := sun.global_transform
	var steps: Array[Vector2] = []
	for tilt: Vector2 in [Vector2.ZERO, Vector2(12.0, 0.0), Vector2(0.0, 12.0)]:
		stage.set_tilt(tilt)
		assert_true(sun.global_transform.is_equal_approx(before), "the light is not on the board")
		var step: Vector2 = floor_material.get_shader_parameter("sun_step")
		var shines: Vector3 = -sun.global_transform.basis.z
		var in_board := board.global_transform.basis.inverse() * shines
		var expected := Vector2(in_board.x, -in_board.y) / -in_board.z
		assert_almost_eq(step.distance_to(expected), 0.0, 0.0001, "cast along the light %s" % tilt)
		steps.append(step)
	assert_gt(steps[0].x, 0.0, "the sun is up on the left: shadows fall to the right")
	assert_gt(steps[0].y, 0.0, "and down the screen")
	# lowering the right (or bottom) edge turns the floor away from a sun on the upper left:
	# its light comes in lower, and the shadows lengthen that way
	assert_gt(steps[1].x, steps[0].x, "the right edge lowered: longer shadows to the right")
	assert_gt(steps[2].y, steps[0].y, "the bottom edge lowered: longer shadows down")


func test_walls_frame_and_balls_each_cast_a_soft_shadow_on_the_floor() -> void:
	var board := _stage().board()
	var floor_material := board.floor_material()
	var level := _rules().level
	var field: ImageTexture = floor_material.get_shader_parameter("wall_field")
	assert_not_null(field, "the floor knows where the walls are")
	assert_almost_eq(
		float(floor_material.get_shader_parameter("wall_height")), board.wall_height_px(), 0.001
	)
	var frame_height: float = floor_material.get_shader_parameter("frame_height")
	assert_gt(frame_height, board.wall_height_px(), "the frame stands above the walls")
	assert_eq(
		board.get_children().filter(func(n: Node) -> bool: return n.name.contains("hadow")), []
	)
	_game._process(0.016)
	var balls: PackedVector4Array = floor_material.get_shader_parameter("balls")
	assert_eq(int(floor_material.get_shader_parameter("ball_count")), level.ball_starts.size())
	var first := _rules().world.get_ball_position(_rules().world.get_ids()[0])
	assert_almost_eq(Vector2(balls[0].x, balls[0].y).distance_to(first), 0.0, 0.01, "where it is")
	assert_almost_eq(balls[0].z, level.ball_radius, 0.01, "its centre a radius above the floor")
	assert_almost_eq(balls[0].w, level.ball_radius, 0.01)


# Software GL spent two thirds of each frame on MSAA: there the 3D board is drawn at a lower
# resolution without it; a graphics card keeps the project's settings, and the window gets
# them back when the maze closes.
func test_software_gl_draws_the_3d_small_without_msaa_and_gives_the_window_back() -> void:
	var project_msaa: int = ProjectSettings.get_setting("rendering/anti_aliasing/quality/msaa_3d")
	var view := SubViewport.new()
	add_child_autofree(view)
	MazeStage.use_render_settings(view, "llvmpipe (LLVM 22.1.8, 256 bits)")
	var scale: float = MazeStage.SOFTWARE_GL_RENDER_SCALE
	assert_lt(scale, 1.0)
	assert_eq(view.scaling_3d_scale, scale)
	assert_eq(view.msaa_3d, Viewport.MSAA_DISABLED)
	MazeStage.use_render_settings(view, "NVIDIA GeForce RTX 3060/PCIe/SSE2")
	assert_eq(view.scaling_3d_scale, 1.0)
	assert_eq(view.msaa_3d, project_msaa)
	var window := _game.get_viewport()
	window.scaling_3d_scale = 0.3
	remove_child(_game)
	assert_eq(window.scaling_3d_scale, 1.0, "the window is given back")
	assert_eq(window.msaa_3d, project_msaa)
	_game.free()


# Bug 1: at full diagonal tilt a corner of the board dropped through the table's shadow.
func test_no_tilt_puts_a_corner_of_the_board_through_the_table() -> void:
	var stage := _stage()
	var table: float = stage.table_height()
	for x in [-12.0, -6.0, 0.0, 6.0, 12.0]:
		for y in [-12.0, -6.0, 0.0, 6.0, 12.0]:
			stage.set_tilt(Vector2(x, y))
			var lowest: float = stage.lowest_board_point()
			assert_gt(lowest, table, "tilt (%s, %s): the board stays above the table" % [x, y])


func test_the_joystick_starts_the_game_and_tilts_the_board() -> void:
	var joystick: Control = _game.get_node("%Joystick")
	assert_true(joystick.get("glowing"), "the head glows until first used")
	joystick.emit_signal("pressed")
	_game._start()
	assert_true(_rules().is_playing())
	joystick.emit_signal("moved", Vector2(40.0, -7.5))
	_game._process(0.016)
	var half := TiltInput.tilt_from_joystick(Vector2(0.0, -7.5)).y
	assert_almost_eq(
		_rules().tilt, Vector2(12.0, half), Vector2(0.01, 0.01), "gently near the centre"
	)
	var shown: Vector2 = _game.get_node("Stage").shown_tilt()
	assert_almost_eq(shown.x, 12.0, 0.01, "the 3D board turns with the tilt")
	assert_almost_eq(shown.y, half, 0.01)


func test_the_head_is_clamped_to_fifteen_pixels() -> void:
	var joystick := _game.get_node("%Joystick") as MazeJoystick
	joystick.head_offset = Vector2(-99.0, 40.0)
	assert_eq(joystick.head_offset, Vector2(-15.0, 15.0))


# QA: the note said "Click the joystick to start!" to a player on the arrows or a pad, whose
# first tilt starts the board: it now says what every way of playing does.
func test_the_note_says_a_tilt_starts_and_keys_tilt_smoothly_not_at_once() -> void:
	assert_eq(
		_note().split("\n")[0],
		"Tilt\u00a0the\u00a0board to\u00a0start!",
		"two phrases: it breaks, if at all, between them (never inside a word)"
	)
	Input.action_press("tilt_right")
	_game._process(1.0 / 60.0)
	assert_true(_rules().is_playing(), "a tilt key starts the game too")
	_game._process(1.0 / 60.0)
	var early := _rules().tilt.x
	assert_between(early, 0.1, 6.0, "eases toward the target")
	for i in 60:
		_game._process(1.0 / 60.0)
	assert_almost_eq(_rules().tilt.x, 12.0, 0.2, "reaches full tilt within a second")


func test_space_h_and_e_reset_and_switch_modes() -> void:
	_game._start()
	_rules().set_tilt(Vector2(12.0, 12.0))
	_rules().advance(0.5)
	_press("maze_hard_mode")
	assert_true(_rules().hard_mode)
	assert_eq(_rules().state, MazeRules.State.READY)
	assert_string_contains(_note(), "avoid the black holes")
	assert_eq(str(_game.get_node("%Mode").text), "HARD MODE")
	_game._start()
	_rules().set_tilt(Vector2(0.0, 12.0))
	_rules().advance(0.5)
	_press("maze_reset")
	assert_true(_rules().hard_mode, "Space keeps the mode")
	assert_eq(_rules().ball_positions(), _rules().level.ball_starts)
	_press("maze_easy_mode")
	assert_false(_rules().hard_mode)
	assert_string_contains(_note(), "Ready for hard mode? Press%sH" % MazeHints.NBSP)


# Bug 3: the README promises R and the gamepad's Back restart both games.
func test_r_and_the_gamepad_back_button_restart_the_maze() -> void:
	var restarts: Array[InputEvent] = []
	var key := InputEventKey.new()
	key.physical_keycode = KEY_R
	key.pressed = true
	restarts.append(key)
	var back := InputEventJoypadButton.new()
	back.button_index = JOY_BUTTON_BACK
	back.pressed = true
	restarts.append(back)
	for event in restarts:
		_game._start()
		_rules().set_tilt(Vector2(12.0, 12.0))
		_rules().advance(0.5)
		assert_ne(_rules().ball_positions(), _rules().level.ball_starts, "the balls rolled")
		_game._unhandled_input(event)
		assert_eq(_rules().state, MazeRules.State.READY, "%s restarts" % event.as_text())
		assert_eq(_rules().ball_positions(), _rules().level.ball_starts)


func test_a_win_shows_the_message_and_saves_the_best_time() -> void:
	var rules := _rules()
	_game._start()
	rules.set_tilt(Vector2(3.0, 0.0))
	rules.advance(0.25)
	var ids := rules.world.get_ids()
	for i in ids.size():
		rules.world.set_ball_position(ids[i], rules.level.goal_center + Vector2(i * 10 - 15, 0))
	rules.step()
	assert_eq(rules.state, MazeRules.State.WON)
	# the card says it was done: the panel does not say it again behind it (a play trial)
	assert_false(_note().contains("did it"), "no second 'you did it' beside the card")
	assert_string_contains(_note(), "Press%sH for hard mode" % MazeHints.NBSP)
	var best := App.best_maze_time(rules.level.board_id, false)
	assert_almost_eq(best, rules.elapsed, 0.001, "the time is saved as the best")


func test_the_next_medal_time_shows_while_playing() -> void:
	var rules := _rules()
	_game._start()
	rules.advance(0.1)
	_game._process(0.016)
	var label: Label = _game.get_node("%NextMedal")
	var gold: float = rules.level.medal_times_easy[0]
	assert_eq(label.text, "Gold by %s" % MazeWinSummary.clock(gold))
	rules.elapsed = gold + 0.5
	_game._process(0.0)
	assert_string_contains(label.text, "Silver by ")


func test_a_win_shows_the_panel_with_medal_best_and_next_board() -> void:
	var rules := _rules()
	var kept := App.save_data
	App.save_data = SaveData.new()  # in memory only: never written
	App.record_maze_time(rules.level.board_id, false, 500.0)
	_game._start()
	rules.advance(0.25)
	var sounds := _game.sounds()
	var played_before := sounds.played_count()
	var ids := rules.world.get_ids()
	for i in ids.size():
		rules.world.set_ball_position(ids[i], rules.level.goal_center + Vector2(i * 10 - 15, 0))
	rules.step()
	var panel := _game.win_panel()
	assert_true(panel.visible, "the win panel shows")
	assert_gte(sounds.played_count() - played_before, 2, "a fanfare and the medal's chime")
	var texts: PackedStringArray = panel.texts()
	assert_eq(texts[0], "Gold!", "a quick finish is gold, said once")
	assert_string_contains(texts[1], MazeWinSummary.clock(rules.elapsed))
	assert_false("Gold" in " ".join(texts.slice(1)), "the medal is not said again")
	assert_string_contains(texts[3], "New best: ")
	var disc := panel.medal_disc()
	assert_true(disc.visible, "the medal won is drawn large")
	assert_eq(disc.get("medal"), Medals.Medal.GOLD)
	assert_gte(disc.get_combined_minimum_size().x, 100.0, "large: over 100 px across")
	var buttons: Array[Button] = panel.buttons()
	assert_true(buttons[0].visible, "classic has a next board")
	assert_eq(buttons[0].text, "Next board")
	await wait_process_frames(2)
	assert_true(buttons[0].has_focus(), "Next board has the keyboard and pad focus")
	assert_eq(buttons[0].focus_neighbor_right, NodePath(), "a row: focus moves by position")
	var fill := (buttons[0].get_theme_stylebox("normal") as StyleBoxFlat).bg_color
	for button: Button in buttons.slice(1):
		var normal := button.get_theme_stylebox("normal") as StyleBoxFlat
		assert_not_null(normal, "%s has the card's own style, not the default grey" % button.text)
		if normal != null:
			assert_eq(normal.bg_color, fill, "%s looks like Next board, not disabled" % button.text)
	buttons[1].pressed.emit()
	assert_eq(rules.state, MazeRules.State.READY, "Retry starts the board again")
	assert_false(panel.visible, "and hides the panel")
	App.save_data = kept


func test_a_loss_names_the_reset_key() -> void:
	var rules := _rules()
	_press("maze_hard_mode")
	_game._start()
	var id := rules.world.get_ids()[0]
	rules.world.set_ball_position(id, rules.level.holes[1] + Vector2(-12.0, 0.0))
	rules.world.set_ball_velocity(id, Vector2(60.0, 0.0))
	for i in 30:
		rules.step()
	assert_eq(rules.state, MazeRules.State.LOST)
	assert_string_contains(_note(), "A ball fell into a black hole: this run can't be won now.")
	assert_string_contains(_note(), "press%sSpace to start again" % MazeHints.NBSP)
