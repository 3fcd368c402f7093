extends GutTest
## The soft shadows' data: the walls' distance field the floor shader reads (zero on a wall's
## centre line, rising smoothly away from it, capped far off), and the way shadows fall for
## a sun shining down along a direction in the board's space.


func _field_px(field: Image, p: Vector2) -> float:
	var texel := Vector2i(p / MazeSoftShadows.FIELD_CELL_PX)
	return field.get_pixel(texel.x, texel.y).r * MazeSoftShadows.FIELD_RANGE_PX


func test_the_wall_field_measures_the_distance_to_the_nearest_wall() -> void:
	var size := Vector2(100, 60)
	var walls := PackedVector2Array(
		[Vector2(20, 30), Vector2(80, 30), Vector2(50, 0), Vector2(50, 10)]
	)
	var field := MazeSoftShadows.wall_field(size, walls)
	assert_eq(
		field.get_size(), Vector2i(50, 30), "a texel every %s px" % MazeSoftShadows.FIELD_CELL_PX
	)
	assert_eq(field.get_format(), Image.FORMAT_L8)
	var step := MazeSoftShadows.FIELD_RANGE_PX / 255.0
	# texel centres sit at odd pixels: (31, 31) is 1 px below the first wall
	assert_almost_eq(_field_px(field, Vector2(31, 31)), 1.0, step, "on the line")
	assert_almost_eq(_field_px(field, Vector2(41, 37)), 7.0, step, "7 px below it")
	assert_almost_eq(
		_field_px(field, Vector2(15, 31)), Vector2(5, 1).length(), step, "past its end"
	)
	assert_almost_eq(
		_field_px(field, Vector2(53, 13)), Vector2(3, 3).length(), step, "the short wall"
	)
	assert_almost_eq(
		_field_px(field, Vector2(5, 55)), MazeSoftShadows.FIELD_RANGE_PX, step, "far off"
	)


func test_the_field_rises_smoothly_so_shadow_edges_come_out_soft() -> void:
	var field := MazeSoftShadows.wall_field(
		Vector2(60, 60), PackedVector2Array([Vector2(0, 30), Vector2(60, 30)])
	)
	var previous := -1.0
	for y in range(30, 46, 2):
		var d := _field_px(field, Vector2(31, y + 1))
		assert_gt(d, previous, "distance grows step by step away from the wall at y %d" % y)
		previous = d


func test_shadows_fall_away_from_the_sun_and_lengthen_as_it_sinks() -> void:
	assert_eq(
		MazeSoftShadows.sun_step(Vector3(0, 0, -1)), Vector2.ZERO, "straight down: under each wall"
	)
	var slanted := MazeSoftShadows.sun_step(Vector3(0.5, 0.5, -1.0))
	assert_almost_eq(slanted.x, 0.5, 0.0001, "to the right")
	assert_almost_eq(slanted.y, -0.5, 0.0001, "mesh y is up the screen: up the board")
	var low := MazeSoftShadows.sun_step(Vector3(1.0, 0.0, -0.5))
	assert_almost_eq(low.x, 2.0, 0.0001, "a low sun casts long shadows")
	assert_eq(
		MazeSoftShadows.sun_step(Vector3(0, 0, 1)), Vector2.ZERO, "a sun below the floor casts none"
	)


func test_a_short_wall_and_an_empty_board_build_a_field() -> void:
	var empty := MazeSoftShadows.wall_field(Vector2(10, 10), PackedVector2Array())
	assert_almost_eq(empty.get_pixel(2, 2).r, 1.0, 0.001, "no walls: far from everything")
	var dot := MazeSoftShadows.wall_field(
		Vector2(10, 10), PackedVector2Array([Vector2(5, 5), Vector2(5, 5)])
	)
	assert_almost_eq(_field_px(dot, Vector2(5, 5)), 0.0, 0.1, "a wall of no length is a point")
	var slanted := MazeSoftShadows.wall_field(
		Vector2(40, 40), PackedVector2Array([Vector2(0, 0), Vector2(40, 40)])
	)
	var step := MazeSoftShadows.FIELD_RANGE_PX / 255.0
	assert_almost_eq(_field_px(slanted, Vector2(21, 21)), 0.0, step, "on a slanted wall")
	assert_almost_eq(_field_px(slanted, Vector2(25, 21)), sqrt(8.0), step, "beside it")
