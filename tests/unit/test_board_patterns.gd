extends GutTest
## PinPatterns give exact positions; PocketStamp builds rims a ball cannot pass with the
## special pin at the bottom.


func test_row_spaces_points_evenly_with_both_ends() -> void:
	var points := PinPatterns.row(Vector2(0, 10), Vector2(30, 10), 4)
	assert_eq(
		points,
		PackedVector2Array([Vector2(0, 10), Vector2(10, 10), Vector2(20, 10), Vector2(30, 10)])
	)
	assert_eq(PinPatterns.row(Vector2(5, 5), Vector2(9, 9), 1), PackedVector2Array([Vector2(5, 5)]))
	assert_eq(PinPatterns.row(Vector2.ZERO, Vector2.ONE, 0).size(), 0)


func test_staggered_lattice_offsets_every_other_row() -> void:
	var points := PinPatterns.staggered_lattice(Rect2(0, 0, 40, 20), Vector2(20, 10))
	var expected := PackedVector2Array(
		[
			Vector2(0, 0),
			Vector2(20, 0),
			Vector2(40, 0),
			Vector2(10, 10),
			Vector2(30, 10),
			Vector2(0, 20),
			Vector2(20, 20),
			Vector2(40, 20),
		]
	)
	assert_eq(points, expected)
	assert_eq(PinPatterns.staggered_lattice(Rect2(0, 0, 10, 10), Vector2(0, 5)).size(), 0)


func test_arc_and_circle() -> void:
	var arc := PinPatterns.arc(Vector2(100, 100), 50.0, 0.0, 90.0, 3)
	assert_almost_eq(arc[0], Vector2(150, 100), Vector2.ONE * 1e-4)
	assert_almost_eq(
		arc[1], Vector2(100 + 50 * cos(PI / 4), 100 + 50 * sin(PI / 4)), Vector2.ONE * 1e-4
	)
	assert_almost_eq(arc[2], Vector2(100, 150), Vector2.ONE * 1e-4, "90° is down (y down)")
	var ring := PinPatterns.circle(Vector2.ZERO, 10.0, 4)
	assert_eq(ring.size(), 4)
	assert_almost_eq(ring[1], Vector2(0, 10), Vector2.ONE * 1e-4)
	assert_almost_eq(ring[3], Vector2(0, -10), Vector2.ONE * 1e-4)


func test_filters() -> void:
	var points := PackedVector2Array([Vector2(0, 0), Vector2(5, 0), Vector2(20, 0)])
	assert_eq(PinPatterns.inside_circle(points, Vector2.ZERO, 10.0).size(), 2)
	var away := PinPatterns.away_from(points, PackedVector2Array([Vector2(6, 0)]), 3.0)
	assert_eq(away, PackedVector2Array([Vector2(0, 0), Vector2(20, 0)]))
	var rects: Array[Rect2] = [Rect2(-1, -1, 2, 2)]
	assert_eq(PinPatterns.outside_rects(points, rects).size(), 2)


func test_rim_gaps_stop_a_ball() -> void:
	var spec := PocketSpec.create(Vector2(100, 100), 22.0, 24.0, 4)
	var pins := PocketStamp.pins_for(spec, 1.5, 5.0)
	var rim := pins.slice(0, pins.size() - 1)
	# Walk the rim in order (the special pin sits between the two halves of the bottom).
	var ordered := PackedVector2Array()
	var half := rim.size() / 2
	ordered.append_array(rim.slice(0, half))
	ordered.append(pins[pins.size() - 1])
	ordered.append_array(rim.slice(half))
	for i in ordered.size() - 1:
		var gap := ordered[i].distance_to(ordered[i + 1]) - 2.0 * 1.5
		assert_lt(gap, 10.0, "a 10 px ball cannot pass between rim pins %d and %d" % [i, i + 1])
		assert_gt(gap, 0.0, "rim pins do not overlap")


func test_special_pin_is_last_and_lowest() -> void:
	var spec := PocketSpec.create(Vector2(100, 100), 22.0, 24.0, 4)
	var pins := PocketStamp.pins_for(spec, 1.5, 5.0)
	var special := pins[pins.size() - 1]
	assert_eq(special, Vector2(100, 124))
	assert_eq(PocketStamp.special_position(spec), special)
	for p in pins:
		assert_lte(p.y, special.y)
		assert_between(p.x, 89.0 - 1e-3, 111.0 + 1e-3, "inside the cup's width")
	assert_eq(pins[0], Vector2(89, 100), "the rim starts at the mouth's left corner")


func test_apply_and_remove_keep_pin_lists_in_step() -> void:
	var level := BoardLevel.new()
	level.ball_radius = 5.0
	level.pin_radius = 1.5
	level.pins = PackedVector2Array([Vector2(10, 10)])
	level.pin_pocket = PackedInt32Array([-1])
	level.pin_special = PackedByteArray([0])
	var pockets: Array[PocketSpec] = [
		PocketSpec.create(Vector2(50, 50), 22.0, 24.0, 4),
		PocketSpec.create(Vector2(150, 50), 22.0, 24.0, 2),
	]
	level.pockets = pockets
	PocketStamp.apply(level, 0)
	PocketStamp.apply(level, 1)
	var stamp_size := PocketStamp.pins_for(pockets[0], 1.5, 5.0).size()
	assert_eq(level.pins.size(), 1 + stamp_size * 2)
	assert_eq(level.pin_pocket.size(), level.pins.size())
	assert_eq(level.pin_special.size(), level.pins.size())
	PocketStamp.apply(level, 0)  # re-stamping replaces, never duplicates
	assert_eq(level.pins.size(), 1 + stamp_size * 2)
	PocketStamp.remove(level, 0)
	assert_eq(level.pockets.size(), 1)
	assert_eq(level.pins.size(), 1 + stamp_size)
	for owner in level.pin_pocket:
		assert_true(owner == -1 or owner == 0, "later pockets are renumbered")


func test_point_grid_finds_every_near_point_and_skips_broken_ones() -> void:
	var points := PackedVector2Array(
		[Vector2(0, 0), Vector2(9, 0), Vector2(25, 0), Vector2(NAN, 0), Vector2(-9, -9)]
	)
	var grid := PointGrid.new(points, 10.0)
	var near := Array(grid.near(Vector2(1, 1)))
	near.sort()
	assert_eq(near, [0, 1, 4], "the far point and the NaN one are not neighbours")
	assert_eq(grid.buckets.size(), 3, "cells (0,0), (2,0), (-1,-1)")
