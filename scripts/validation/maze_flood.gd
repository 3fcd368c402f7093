class_name MazeFlood
extends RefCounted
## Free space of a maze for a ball's centre, on a grid; answers "can this start reach the
## goal?" with connected regions labelled once.

## The flood fill grid has at most about this many cells (keeps live validation fast).
const MAX_CELLS := 40000.0

## Grid cell size in pixels, and the grid's size in cells.
var cell: float
var cols: int
var rows: int
## Per cell: 1 where a ball's centre fits, 0 where a wall (grown by the ball) or edge is.
var free := PackedByteArray()
## Per cell: the connected region reached from some ball start, or -1.
var region := PackedInt32Array()
## Regions (as keys) that reach into the goal.
var goal_regions := {}
var _level: BoardLevel


## Free space of `level`; with `holes_block` the black holes count as blocked. `walls_free`,
## the `free` grid of a flood of the same level without holes, saves redoing the walls (the
## costly part).
func _init(
	level: BoardLevel, holes_block: bool, walls_free: PackedByteArray = PackedByteArray()
) -> void:
	_level = level
	cell = maxf(level.ball_radius * 0.75, sqrt(level.size.x * level.size.y / MAX_CELLS))
	cols = maxi(1, ceili(level.size.x / cell))
	rows = maxi(1, ceili(level.size.y / cell))
	free.resize(cols * rows)
	free.fill(1)
	region.resize(cols * rows)
	region.fill(-1)
	if walls_free.size() == cols * rows:
		free = walls_free.duplicate()
	else:
		_block_edges()
		var grow := wall_grow()
		@warning_ignore("integer_division")  # walls are pairs of points; a lone end is ignored
		var wall_count := level.walls.size() / 2
		for w in wall_count:
			_block_capsule(level.walls[w * 2], level.walls[w * 2 + 1], grow)
	if holes_block:
		for hole in level.holes:
			_block_capsule(hole, hole, level.hole_radius)
	_label_regions()


## True when a ball's centre at `start` can roll into the goal.
func reaches_goal(start: Vector2) -> bool:
	var index := _index_of(start)
	return index >= 0 and goal_regions.has(region[index])


## The connected region a ball's centre at `p` is in (a region some ball start reaches), or
## -1 off the board, inside a wall or in a part no start reaches.
func region_at(p: Vector2) -> int:
	var index := _index_of(p)
	return region[index] if index >= 0 else -1


## As region_at, but a ball resting against a wall (its centre a hair inside the grid's
## blocked band, as the felt-lined board of maze rules 5 leaves them) takes the region of
## the nearest free cell next to it.
func region_near(p: Vector2) -> int:
	var label := region_at(p)
	if label >= 0:
		return label
	var best := INF
	for dy in range(-1, 2):
		for dx in range(-1, 2):
			var q := p + Vector2(dx, dy) * cell
			var there := region_at(q)
			if there >= 0 and q.distance_to(p) < best:
				best = q.distance_to(p)
				label = there
	return label


## True when region `label` (region_at) joins the goal.
func region_reaches_goal(label: int) -> bool:
	return goal_regions.has(label)


## The grid cell holding `p` (row * cols + column), or -1 off the grid.
func cell_of(p: Vector2) -> int:
	return _index_of(p)


func _index_of(p: Vector2) -> int:
	var cx := floori(p.x / cell)
	var cy := floori(p.y / cell)
	if cx < 0 or cy < 0 or cx >= cols or cy >= rows:
		return -1
	return cy * cols + cx


# Cells whose centre is closer than a ball radius to the board's edge.
func _block_edges() -> void:
	var r := _level.ball_radius
	var x_lo := ceili(r / cell - 0.5)
	var x_hi := floori((_level.size.x - r) / cell - 0.5)
	var y_lo := ceili(r / cell - 0.5)
	var y_hi := floori((_level.size.y - r) / cell - 0.5)
	for cy in rows:
		for cx in cols:
			if cx < x_lo or cx > x_hi or cy < y_lo or cy > y_hi:
				free[cy * cols + cx] = 0


# Blocks the cells whose centre is closer than `grow` to the segment a-b.
func _block_capsule(a: Vector2, b: Vector2, grow: float) -> void:
	for index in capsule_cells(a, b, grow):
		free[index] = 0


## How far a wall blocks the grid on each side of its centre line: half its width plus a
## ball's radius (a hair less, so a gap exactly a ball wide stays open).
func wall_grow() -> float:
	return _level.wall_width * 0.5 + _level.ball_radius - minf(0.5, cell * 0.25)


## The cells whose centre is closer than `grow` to the segment a-b. Each row only visits
## the cells beside the part of the segment within `grow` of that row, so the work follows
## the wall's length times its width, never the area of its bounding box.
func capsule_cells(a: Vector2, b: Vector2, grow: float) -> PackedInt32Array:
	var cells := PackedInt32Array()
	var box := Rect2(a, Vector2.ZERO).expand(b).grow(grow)
	var y0 := maxi(0, floori(box.position.y / cell))
	var y1 := mini(rows - 1, floori(box.end.y / cell))
	var grow2 := grow * grow
	var ab := b - a
	var len2 := ab.length_squared()
	for cy in range(y0, y1 + 1):
		var py := (cy + 0.5) * cell
		var span := _row_span(a, ab, py, grow)
		var x0 := maxi(0, floori(span.x / cell))
		var x1 := mini(cols - 1, floori(span.y / cell))
		for cx in range(x0, x1 + 1):
			var px := (cx + 0.5) * cell
			var t := 0.0
			if len2 > 0.0:
				t = clampf(((px - a.x) * ab.x + (py - a.y) * ab.y) / len2, 0.0, 1.0)
			var dx := px - (a.x + ab.x * t)
			var dy := py - (a.y + ab.y * t)
			if dx * dx + dy * dy < grow2:
				cells.append(cy * cols + cx)
	return cells


# The x range (as x..y) holding every point of row `py` within `grow` of the segment
# a + ab * t: only the part of the segment within `grow` of the row can be that close.
static func _row_span(a: Vector2, ab: Vector2, py: float, grow: float) -> Vector2:
	var t0 := 0.0
	var t1 := 1.0
	if absf(ab.y) > 1e-9:
		var first := (py - grow - a.y) / ab.y
		var second := (py + grow - a.y) / ab.y
		t0 = clampf(minf(first, second), 0.0, 1.0)
		t1 = clampf(maxf(first, second), 0.0, 1.0)
	var x_at_t0 := a.x + ab.x * t0
	var x_at_t1 := a.x + ab.x * t1
	return Vector2(minf(x_at_t0, x_at_t1) - grow, maxf(x_at_t0, x_at_t1) + grow)


func _label_regions() -> void:
	var label := 0
	var queue := PackedInt32Array()
	queue.resize(free.size())
	var goal := _level.goal_center
	var goal2 := _level.goal_radius * _level.goal_radius
	for start in _level.ball_starts:
		var seed_index := _index_of(start)
		if seed_index < 0 or free[seed_index] == 0 or region[seed_index] >= 0:
			continue
		region[seed_index] = label
		queue[0] = seed_index
		var head := 0
		var tail := 1
		while head < tail:
			var index := queue[head]
			head += 1
			var cx := index % cols
			@warning_ignore("integer_division")  # the grid row of a cell index
			var cy := index / cols
			var gx := (cx + 0.5) * cell - goal.x
			var gy := (cy + 0.5) * cell - goal.y
			if gx * gx + gy * gy < goal2:
				goal_regions[label] = true
			for k in 4:
				var n := index
				if k == 0 and cx > 0:
					n = index - 1
				elif k == 1 and cx < cols - 1:
					n = index + 1
				elif k == 2 and cy > 0:
					n = index - cols
				elif k == 3 and cy < rows - 1:
					n = index + cols
				if n != index and free[n] == 1 and region[n] < 0:
					region[n] = label
					queue[tail] = n
					tail += 1
		label += 1
