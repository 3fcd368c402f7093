extends GutTest
## Balls you can see on the wood look (trial 8: "the steel balls are small grey dots on light
## wood, and I kept losing them"; the steel's colour had the maple's luminance, 0.80). In
## rendered frames at 1280x720 (tools/maze_board_shots.sh) the ball's middle went from 0.54-0.55
## against the floor's 0.60 to 0.31 against 0.60.

const BOARD := "res://levels/maze/switchbacks.board"


func _balls(tutorial: bool, low: bool) -> MazeBalls3d:
	var rules := MazeRules.new(BoardLoader.load_board(BOARD).level)
	var balls: MazeBalls3d = add_child_autofree(MazeBalls3d.new())
	balls.set_material(MazeBallMaterial.make(tutorial, low), MazeBallMaterial.rim(tutorial))
	balls.sync(rules, 0.0)
	return balls


func _first_ball(balls: MazeBalls3d) -> MeshInstance3D:
	return balls.get_child(0) as MeshInstance3D


func test_steel_is_far_darker_than_the_maple_floor() -> void:
	var floor_luma := MazeBoard3d.MAPLE.get_luminance()
	var steel := MazeBallMaterial.make(false)
	var texture := steel.albedo_texture as ImageTexture
	var middle := texture.get_image().get_pixel(3, 3)  # away from the band
	gut.p("maple %.2f, steel %.2f" % [floor_luma, middle.get_luminance()])
	assert_gt(floor_luma - middle.get_luminance(), 0.3, "the steel stands out dark on maple")


func test_every_steel_ball_has_a_dark_rim_in_both_graphics_settings() -> void:
	for low: bool in [false, true]:
		var balls := _balls(false, low)
		assert_gt(balls.get_child_count(), 0, "balls drawn")
		for ball: MeshInstance3D in balls.get_children():
			var rim := balls.rim_of(ball)
			assert_not_null(rim, "low %s: the ball has a rim" % low)
			if rim == null:
				continue
			var surface := rim.material_override as StandardMaterial3D
			assert_lt(surface.albedo_color.get_luminance(), 0.1, "a dark rim")
			assert_eq(surface.cull_mode, BaseMaterial3D.CULL_FRONT, "only its edge shows")
			assert_gt(rim.scale.x, 1.0, "wider than the ball")


func test_the_tutorial_look_needs_no_rim_and_a_switch_takes_it_away() -> void:
	var balls := _balls(true, false)
	assert_null(balls.rim_of(_first_ball(balls)), "red balls on white: no rim")
	balls.set_material(MazeBallMaterial.make(false), MazeBallMaterial.rim(false))
	assert_not_null(balls.rim_of(_first_ball(balls)), "switched to the wood look: rims")
	balls.set_material(MazeBallMaterial.make(true), MazeBallMaterial.rim(true))
	assert_null(balls.rim_of(_first_ball(balls)), "and back: gone")
