class_name MazeSoftShadows
extends RefCounted
## What the floor shader needs to lay soft shadows (maze_floor_shade.gdshaderinc): a distance
## field of the board's walls (built once per board), the way shadows fall for the sun as the
## board is tilted now, and the balls that cast them. Board pixels, y down.

## The field's texel size and the farthest distance it tells apart (px): a wall's shadow
## reaches its half width plus its penumbra from the wall's centre line, well inside that.
const FIELD_CELL_PX := 2.0
const FIELD_RANGE_PX := 16.0
## The floor shader's limit on balls that cast a shadow (the rest cast none).
const MAX_BALLS := 16


## The distance from each texel's centre to the nearest wall's centre line, over a board
## `size` px big, as 0..255 for 0..FIELD_RANGE_PX (a one-channel image, FIELD_CELL_PX per
## texel). `walls` holds pairs of ends.
static func wall_field(size: Vector2, walls: PackedVector2Array) -> Image:
	var cols := maxi(ceili(size.x / FIELD_CELL_PX), 1)
	var rows := maxi(ceili(size.y / FIELD_CELL_PX), 1)
	var cell := Vector2(size.x / cols, size.y / rows)
	var nearest := PackedFloat32Array()
	nearest.resize(cols * rows)
	nearest.fill(FIELD_RANGE_PX)
	for w in range(walls.size() >> 1):
		_stamp_wall(nearest, Vector2i(cols, rows), cell, walls[w * 2], walls[w * 2 + 1])
	var bytes := PackedByteArray()
	bytes.resize(cols * rows)
	for k in nearest.size():
		bytes[k] = roundi(nearest[k] / FIELD_RANGE_PX * 255.0)
	return Image.create_from_data(cols, rows, false, Image.FORMAT_L8, bytes)


# Lowers `nearest` (a cols × rows grid of texels `cell` px big) to the distance from each
# texel's centre to the wall from `a` to `b`, within FIELD_RANGE_PX of it. The distance
# is split per axis (along the wall and across it) into per-column and per-row squares, so
# the loop over texels only adds and compares (a board opens with its field built).
static func _stamp_wall(
	nearest: PackedFloat32Array, grid: Vector2i, cell: Vector2, a: Vector2, b: Vector2
) -> void:
	var lo := ((a.min(b) - Vector2.ONE * FIELD_RANGE_PX) / cell).floor()
	var hi := ((a.max(b) + Vector2.ONE * FIELD_RANGE_PX) / cell).ceil()
	var i0 := maxi(int(lo.x), 0)
	var i1 := mini(int(hi.x), grid.x)
	var j0 := maxi(int(lo.y), 0)
	var j1 := mini(int(hi.y), grid.y)
	var range_squared := FIELD_RANGE_PX * FIELD_RANGE_PX
	if not is_equal_approx(a.x, b.x) and not is_equal_approx(a.y, b.y):
		# a slanted wall: the full distance to the segment for each texel
		for j in range(j0, j1):
			for i in range(i0, i1):
				var p := Vector2((i + 0.5) * cell.x, (j + 0.5) * cell.y)
				var k := j * grid.x + i
				nearest[k] = minf(nearest[k], segment_distance(p, a, b))
		return
	# along x and along y: how far outside the wall's extent each column and row lies
	var x_lo := minf(a.x, b.x)
	var x_hi := maxf(a.x, b.x)
	var y_lo := minf(a.y, b.y)
	var y_hi := maxf(a.y, b.y)
	var column_squares := PackedFloat32Array()
	column_squares.resize(i1 - i0)
	for i in range(i0, i1):
		var x := (i + 0.5) * cell.x
		var dx := maxf(maxf(x_lo - x, x - x_hi), 0.0)
		column_squares[i - i0] = dx * dx
	for j in range(j0, j1):
		var y := (j + 0.5) * cell.y
		var dy := maxf(maxf(y_lo - y, y - y_hi), 0.0)
		var row_square := dy * dy
		if row_square >= range_squared:
			continue
		var row := j * grid.x
		for i in range(i0, i1):
			var d_squared := row_square + column_squares[i - i0]
			var k := row + i
			var old := nearest[k]
			if d_squared < old * old:
				nearest[k] = sqrt(d_squared)


## The distance from `p` to the segment from `a` to `b`.
static func segment_distance(p: Vector2, a: Vector2, b: Vector2) -> float:
	var ab := b - a
	var length_squared := ab.length_squared()
	var t := (
		0.0 if length_squared < 0.000001 else clampf((p - a).dot(ab) / length_squared, 0.0, 1.0)
	)
	return p.distance_to(a + ab * t)


## How far (board px, y down) a shadow moves across the floor for each px of height it is
## cast from, for light travelling along `sun` in the board's mesh space (x right, y up the
## screen, z out of the floor). Zero when the sun does not shine down onto the floor.
static func sun_step(sun: Vector3) -> Vector2:
	if sun.z >= -0.0001:
		return Vector2.ZERO
	return Vector2(sun.x, -sun.y) / -sun.z
