extends GutTest
## The tilt maze's two looks: wood and steel by default (grained maple floor, walnut walls
## with lighter tops, polished steel balls reflecting a made-up room, a translucent steel
## ghost) and the tutorial's flat colours with red balls, chosen by a saved setting.

const PATH := "user://test_maze_look_settings.cfg"


func after_all() -> void:
	DirAccess.remove_absolute(ProjectSettings.globalize_path(PATH))


func _stage(tutorial: bool) -> MazeStage:
	var stage := MazeStage.new()
	stage.tutorial_look = tutorial
	add_child_autofree(stage)
	stage.set_level(BoardLoader.load_board("res://levels/maze/classic.board").level, false)
	return stage


func _floor_value(stage: MazeStage, name: String) -> Variant:
	var floor_part: MeshInstance3D = stage.board().part("floor")
	return (floor_part.material_override as ShaderMaterial).get_shader_parameter(name)


func _wall_value(stage: MazeStage, name: String) -> Variant:
	var walls: MeshInstance3D = stage.board().part("walls")
	return (walls.material_override as ShaderMaterial).get_shader_parameter(name)


func test_the_look_is_a_setting_that_defaults_to_wood_and_is_saved() -> void:
	var settings := GameSettings.new()
	assert_false(settings.maze_tutorial_look, "wood and steel by default")
	settings.set_value("maze_tutorial_look", true)
	assert_eq(settings.save_file(PATH), OK)
	var loaded := GameSettings.new()
	assert_eq(loaded.load_file(PATH), "")
	assert_true(loaded.maze_tutorial_look, "kept in the file")
	loaded.reset_to_defaults()
	assert_false(loaded.maze_tutorial_look)


func test_wood_and_steel_grain_the_floor_light_the_wall_tops_and_polish_the_balls() -> void:
	var stage := _stage(false)
	assert_gt(float(_floor_value(stage, "grain_strength")), 0.0, "the floor has grain")
	assert_ne(_wall_value(stage, "side_color"), _wall_value(stage, "cap_color"), "lighter tops")
	assert_gt(float(_wall_value(stage, "grain_strength")), 0.0, "stained walls")
	var steel: StandardMaterial3D = stage.balls().material
	assert_gt(steel.metallic, 0.9, "steel")
	assert_lt(steel.roughness, 0.2, "polished enough to show the room")


func test_the_tutorial_look_is_the_seeds_flat_paint_and_red_balls() -> void:
	var stage := _stage(true)
	assert_eq(float(_floor_value(stage, "grain_strength")), 0.0, "a flat floor")
	assert_eq(_floor_value(stage, "floor_color"), MazePalette.BACKGROUND)
	assert_eq(_wall_value(stage, "side_color"), MazePalette.WALL)
	assert_eq(_wall_value(stage, "cap_color"), MazePalette.WALL, "flat walls")
	var red: StandardMaterial3D = stage.balls().material
	assert_eq(red.metallic, 0.0, "not steel")
	var tint := red.albedo_texture.get_image().get_pixel(0, 0)
	assert_true(tint.is_equal_approx(MazePalette.BALL), "the seed's red: %s" % tint)


func test_the_room_the_balls_reflect_has_lamps_windows_and_a_dark_floor() -> void:
	var room := MazeStage.room_panorama(Vector2i(256, 128))
	var lamp := room.get_pixel(int(0.2 * 256), int(0.12 * 128))
	var window := room.get_pixel(int(0.5 / 3.0 * 256), int(0.4 * 128))
	var floor_colour := room.get_pixel(10, 120)
	assert_gt(lamp.get_luminance(), 0.9, "a lamp on the ceiling")
	assert_gt(window.get_luminance(), 0.9, "a window in the wall")
	assert_lt(floor_colour.get_luminance(), 0.25, "a dark floor")


func test_the_ghost_is_a_round_translucent_steel_ball() -> void:
	var ghost := MazeGhost3d.new()
	add_child_autofree(ghost)
	ghost.show_balls(PackedVector2Array([Vector2(50, 50)]), 5.0)
	var ball := ghost.get_child(0) as MeshInstance3D
	var sphere := ball.mesh as SphereMesh
	assert_gte(sphere.radial_segments, 24, "round at the size balls are drawn")
	var look := ball.material_override as ShaderMaterial
	assert_lt(float(look.get_shader_parameter("opacity")), 0.6, "the board shows through")
	assert_string_contains(look.shader.code, "reflect(", "it reflects like steel")
