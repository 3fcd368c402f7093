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
		var a := walls[w * 2]
		var b := walls[w * 2 + 1]
		var lo := (a.min(b) - Vector2.ONE * FIELD_RANGE_PX) / cell
		var hi := (a.max(b) + Vector2.ONE * FIELD_RANGE_PX) / cell
		for j in range(maxi(floori(lo.y), 0), mini(ceili(hi.y), rows)):
			for i in range(maxi(floori(lo.x), 0), mini(ceili(hi.x), cols)):
				var p := Vector2((i + 0.5) * cell.x, (j + 0.5) * cell.y)
				var d := segment_distance(p, a, b)
				var k := j * cols + i
				if d < nearest[k]:
					nearest[k] = d
	var bytes := PackedByteArray()
	bytes.resize(cols * rows)
	for k in nearest.size():
		bytes[k] = roundi(nearest[k] / FIELD_RANGE_PX * 255.0)
	return Image.create_from_data(cols, rows, false, Image.FORMAT_L8, bytes)


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
