extends GutTest
## The geometry behind the 3D maze: balls roll by their motion, a fall sinks and shrinks,
## the board's shadow is cast along the sun, and the meshes come out where the level says.


func test_a_ball_rolled_a_quarter_turn_turns_a_quarter_about_up_cross_motion() -> void:
	var radius := 5.0
	var quarter := Vector3(PI * radius * 0.5, 0.0, 0.0)  # a quarter of the way round, right
	var turned := MazeBalls3d.roll(Basis.IDENTITY, quarter, radius)
	# the point on top (toward the viewer, +z) comes round to the front of the motion (+x)
	assert_almost_eq((turned * Vector3.BACK).distance_to(Vector3.RIGHT), 0.0, 0.0001)
	var down := MazeBalls3d.roll(Basis.IDENTITY, Vector3(0.0, -PI * radius * 0.5, 0.0), radius)
	assert_almost_eq((down * Vector3.BACK).distance_to(Vector3.DOWN), 0.0, 0.0001)


func test_rolling_nowhere_keeps_the_orientation() -> void:
	var start := Basis.from_euler(Vector3(0.3, 0.2, 0.1))
	assert_true(MazeBalls3d.roll(start, Vector3.ZERO, 5.0).is_equal_approx(start))
	assert_true(MazeBalls3d.roll(start, Vector3.RIGHT, 0.0).is_equal_approx(start))


func test_a_fall_slides_to_the_centre_then_sinks_and_shrinks() -> void:
	var start := MazeBalls3d.fall_pose(0.0, 12.0, 5.0)
	assert_eq(start, Vector3(0.0, 0.0, 1.0), "it begins where the ball was")
	var half := MazeBalls3d.fall_pose(MazeBalls3d.FALL_SECONDS * 0.5, 12.0, 5.0)
	assert_eq(half.x, 1.0, "at the centre by half way")
	assert_between(half.y, 1.0, 16.0, "sinking")
	var end := MazeBalls3d.fall_pose(MazeBalls3d.FALL_SECONDS * 3.0, 12.0, 5.0)
	assert_almost_eq(end.y, 17.0, 0.0001, "the whole ball below the floor, at the bottom")
	assert_lt(end.z, 0.6, "and shrunk into the dark")


func test_the_board_shadow_is_cast_along_the_sun() -> void:
	var square := PackedVector3Array(
		[Vector3(0, 0, 0), Vector3(1, 0, 0), Vector3(1, 1, 0), Vector3(0, 1, 0)]
	)
	var straight := MazeTableShadow.outline(square, Vector3(0, 0, -1), -2.0)
	assert_eq(straight.size(), 4, "straight down: the same square")
	var slanted := MazeTableShadow.outline(square, Vector3(0.5, 0, -1), -2.0)
	var min_x := INF
	for p in slanted:
		min_x = minf(min_x, p.x)
	assert_almost_eq(min_x, 1.0, 0.0001, "2 units down at a 1:2 slant moves it 1 across")
	assert_eq(MazeTableShadow.outline(square, Vector3(0, 0, 1), -2.0).size(), 0, "sun below")


func test_walls_are_extruded_capsules_where_the_level_puts_them() -> void:
	var size := Vector2(200.0, 100.0)
	var ends := PackedVector2Array([Vector2(50, 50), Vector2(150, 50)])
	var mesh := MazeMeshes.walls(size, ends, 10.0, 12.0)
	var box := mesh.get_aabb()
	assert_almost_eq(box.position.x, -0.55, 0.0001, "the left cap reaches 5 px past the end")
	assert_almost_eq(box.end.x, 0.55, 0.0001)
	assert_almost_eq(box.size.y, 0.1, 0.0001, "10 px wide")
	assert_almost_eq(box.end.z, 0.12, 0.0001, "12 px high")
	assert_null(MazeMeshes.walls(size, PackedVector2Array(), 10.0, 12.0), "no walls, no mesh")


func test_every_wall_face_looks_outward() -> void:
	var size := Vector2(200.0, 100.0)
	var mesh := MazeMeshes.walls(
		size, PackedVector2Array([Vector2(50, 50), Vector2(150, 50)]), 10, 12
	)
	var arrays := mesh.surface_get_arrays(0)
	var verts: PackedVector3Array = arrays[Mesh.ARRAY_VERTEX]
	var normals: PackedVector3Array = arrays[Mesh.ARRAY_NORMAL]
	var indices: PackedInt32Array = arrays[Mesh.ARRAY_INDEX]
	var wrong := 0
	for t in range(0, indices.size(), 3):
		var a := verts[indices[t]]
		var b := verts[indices[t + 1]]
		var c := verts[indices[t + 2]]
		var facing := normals[indices[t]] + normals[indices[t + 1]] + normals[indices[t + 2]]
		# Godot's front faces are clockwise: the right-hand normal points away from the front
		if (b - a).cross(c - a).dot(facing) > 0.0:
			wrong += 1
	assert_eq(wrong, 0, "no triangle is wound against its normals (culled from the front)")
