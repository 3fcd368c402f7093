extends GutTest
## Low graphics (Settings, "Tilt Maze graphics"): the maze drops its costly looks (soft
## shadows, wood grain, the table's shadow, reflections in the balls) at once, on a board
## already in play, and brings them back; the setting is kept in the settings file.

const GAME := preload("res://scenes/maze/maze_game.tscn")
const TEST_SETTINGS := "user://test_low_graphics_settings.cfg"
const TEST_SAVE := "user://test_low_graphics_save.cfg"

var _game: MazeGame


func before_all() -> void:
	App.load_player_files(TEST_SETTINGS, TEST_SAVE)


func after_all() -> void:
	App.settings.set_value("maze_low_graphics", false)
	App.load_player_files(App.SETTINGS_PATH, App.SAVE_PATH)
	for path in [TEST_SETTINGS, TEST_SAVE]:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(path))


func before_each() -> void:
	App.settings.set_value("maze_low_graphics", false)
	_game = GAME.instantiate()
	add_child_autofree(_game)
	await wait_process_frames(2)


func _floor_uniform(uniform: String) -> Variant:
	return _game.stage().board().floor_material().get_shader_parameter(uniform)


func _wall_grain() -> float:
	var walls := _game.stage().board().part("walls").material_override as ShaderMaterial
	return walls.get_shader_parameter("grain_strength")


func _reflections() -> int:
	return _game.stage().environment().reflected_light_source


func _table_visible() -> bool:
	return _game.stage().table().visible


func test_full_look_has_shadows_grain_table_and_reflections() -> void:
	assert_true(_floor_uniform("shadows_on"))
	assert_gt(_floor_uniform("grain_strength"), 0.0)
	assert_gt(_wall_grain(), 0.0)
	assert_true(_table_visible())
	assert_eq(_reflections(), Environment.REFLECTION_SOURCE_SKY)


func test_the_setting_turns_the_costly_looks_off_in_play_and_back_on() -> void:
	App.settings.set_value("maze_low_graphics", true)
	App.settings.changed.emit()
	assert_false(_floor_uniform("shadows_on"), "no soft shadows")
	assert_eq(_floor_uniform("grain_strength"), 0.0, "a plain floor")
	assert_eq(_wall_grain(), 0.0, "plain walls")
	assert_false(_table_visible(), "no table shadow")
	assert_eq(_reflections(), Environment.REFLECTION_SOURCE_DISABLED, "no reflections")
	assert_null(_game.stage().environment().sky, "no sky for them either (it cost on its own)")
	App.settings.set_value("maze_low_graphics", false)
	App.settings.changed.emit()
	assert_true(_floor_uniform("shadows_on"))
	assert_gt(_floor_uniform("grain_strength"), 0.0)
	assert_true(_table_visible())
	assert_eq(_reflections(), Environment.REFLECTION_SOURCE_SKY)
	assert_not_null(_game.stage().environment().sky, "the room to reflect is back")


func test_a_board_opened_with_the_setting_on_starts_low() -> void:
	App.settings.set_value("maze_low_graphics", true)
	var game: MazeGame = GAME.instantiate()
	add_child_autofree(game)
	await wait_process_frames(2)
	assert_true(game.stage().low_graphics)
	var floor_material := game.stage().board().floor_material()
	assert_false(floor_material.get_shader_parameter("shadows_on"))
	assert_false(game.stage().table().visible)


func test_balls_on_the_board_take_the_low_surface_at_once() -> void:
	await wait_physics_frames(3)
	var balls := _game.stage().balls()
	assert_gt(balls.get_child_count(), 0, "balls are on the board")
	App.settings.set_value("maze_low_graphics", true)
	App.settings.changed.emit()
	for ball: MeshInstance3D in balls.get_children():
		var surface := ball.material_override as StandardMaterial3D
		assert_eq(surface.metallic, 0.0, "no mirror steel without reflections to show")


func test_the_setting_is_kept_in_the_settings_file() -> void:
	var settings := GameSettings.new()
	settings.set_value("maze_low_graphics", true)
	var path := "user://test_low_graphics_round_trip.cfg"
	assert_eq(settings.save_file(path), OK)
	var loaded := GameSettings.new()
	assert_eq(loaded.load_file(path), "")
	assert_true(loaded.maze_low_graphics)
	DirAccess.remove_absolute(ProjectSettings.globalize_path(path))


# On software GL a scaled 3D picture costs an extra buffer and a smoothed copy, more than
# the pixels it saves once the floor is plain: Low draws straight to the window, no MSAA.
func test_low_draws_software_gl_at_full_size_without_msaa() -> void:
	var view := SubViewport.new()
	add_child_autofree(view)
	MazeStage.use_render_settings(view, "llvmpipe (LLVM 22.1.8, 256 bits)", true)
	assert_eq(view.scaling_3d_scale, 1.0)
	assert_eq(view.msaa_3d, Viewport.MSAA_DISABLED)
	MazeStage.use_render_settings(view, "llvmpipe (LLVM 22.1.8, 256 bits)", false)
	assert_eq(view.scaling_3d_scale, MazeStage.SOFTWARE_GL_RENDER_SCALE)
	var project_msaa: int = ProjectSettings.get_setting("rendering/anti_aliasing/quality/msaa_3d")
	MazeStage.use_render_settings(view, "NVIDIA GeForce RTX 3060/PCIe/SSE2", true)
	assert_eq(view.scaling_3d_scale, 1.0, "a graphics card keeps its settings")
	assert_eq(view.msaa_3d, project_msaa)


# The walls were Low's largest cost on software GL (tools/maze_fps.sh): Low draws them with
# square ends and no chamfer, a fraction of the triangles, and the full look gets its
# rounded walls back.
func test_low_draws_the_walls_with_far_fewer_triangles() -> void:
	var board := _game.stage().board()
	var full := board.wall_triangles()
	App.settings.set_value("maze_low_graphics", true)
	App.settings.changed.emit()
	var low := board.wall_triangles()
	gut.p("wall triangles on Classic: full look %d, Low %d" % [full, low])
	assert_lt(low * 3, full, "Low: %d triangles, the full look %d" % [low, full])
	var ball := _game.stage().balls().material as StandardMaterial3D
	assert_eq(ball.shading_mode, BaseMaterial3D.SHADING_MODE_PER_VERTEX, "balls lit per vertex")
	App.settings.set_value("maze_low_graphics", false)
	App.settings.changed.emit()
	assert_eq(board.wall_triangles(), full, "the rounded walls come back")


# The lit, shadowed floor was Low's largest cost after the walls (tools/maze_fps.sh, "Low,
# no floor"): Low paints it with an unshaded shader that keeps the goal and the holes (no
# lighting, no discard), with the board's paint (goal, colours) carried over, and the full
# look gets its lit floor back.
func test_low_paints_the_floor_unshaded_and_keeps_the_goal() -> void:
	var board := _game.stage().board()
	var goal: Vector2 = _floor_uniform("goal_center")
	App.settings.set_value("maze_low_graphics", true)
	App.settings.changed.emit()
	var low_shader := board.floor_material().shader
	assert_eq(low_shader, MazeBoard3d.FLOOR_LOW_SHADER, "Low's own floor shader")
	assert_eq(low_shader.get_mode(), Shader.MODE_SPATIAL)
	assert_string_contains(low_shader.code, "unshaded")
	assert_false(low_shader.code.contains("discard"), "holes painted, not cut out")
	assert_eq(_floor_uniform("goal_center"), goal, "the goal is where it was")
	assert_gt(_floor_uniform("low_light"), 0.0, "the floor is not black")
	App.settings.set_value("maze_low_graphics", false)
	App.settings.changed.emit()
	assert_eq(board.floor_material().shader, MazeBoard3d.FLOOR_SHADER, "the lit floor is back")


# The Low floor was still Low's largest cost: each of its pixels worked out the goal's dish
# and every hole's rim (tools/maze_fps.sh: 41.7 frames per CPU second, 61.5 without the
# floor; 27.4 with holes, their tubes drawn). Low's floor is one colour now, and the goal and
# holes are a small mesh of their own above it (MazeLowMarks), with no tubes under them.
func test_low_floor_is_one_colour_and_the_goal_and_holes_are_their_own_mesh() -> void:
	var board := _game.stage().board()
	assert_false(board.part("marks").visible, "the full look paints the goal in its floor")
	App.settings.set_value("maze_low_graphics", true)
	App.settings.changed.emit()
	var code := ""
	for line in board.floor_material().shader.code.split("\n"):
		if not line.strip_edges().begins_with("//"):
			code += line + "\n"
	for painted in ["goal", "hole", "smoothstep", "distance"]:
		assert_false(code.contains(painted), "Low's floor works out no '%s'" % painted)
	var marks := board.part("marks")
	assert_true(marks.visible, "the goal is drawn on Low")
	var easy_vertices := _vertex_count(marks)
	assert_gt(easy_vertices, 0, "the goal's dish has a mesh")
	# The goal's dish lies inside its lip, round the goal's centre.
	var box := marks.get_aabb()
	var level := _game.rules.level
	var goal_span := (level.goal_radius + MazeBoard3d.GOAL_LIP_PX) * 2.0 * MazeMeshes.UNITS_PER_PX
	assert_almost_eq(box.size.x, goal_span, 0.01, "the dish reaches to its lip")
	assert_gt(box.position.z, 0.0, "above the floor")
	board.set_hard_mode(true)
	if level.holes.is_empty():
		return
	assert_gt(_vertex_count(marks), easy_vertices, "hard mode's holes are drawn on Low")
	assert_false(board.part("holes").visible, "no hole tubes on Low: the marks paint them")
	App.settings.set_value("maze_low_graphics", false)
	App.settings.changed.emit()
	assert_false(marks.visible, "the full look is back")
	assert_true(board.part("holes").visible, "with its hole tubes")
	board.set_hard_mode(false)


func _vertex_count(part: MeshInstance3D) -> int:
	if part.mesh == null:
		return 0
	return (part.mesh as ArrayMesh).surface_get_array_len(0)
