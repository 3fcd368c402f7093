class_name StaticGeometry
extends RefCounted
## The uniform grid a BallWorld's static shapes are binned into ("pin zoning"). It owns the
## shapes (`shapes`, StaticShapes: the flat arrays and the checked calls that add them) and
## only reads them: one job each, by composition. Internal to scripts/physics: BallWorld
## owns one.
##
## A grid cell lists every pin and wall whose shape, grown by the largest ball radius and a
## margin, touches the cell; so a ball only tests the shapes of the one cell its centre is in.
## Lists are stored flat (CSR): items of cell c are items[start[c] .. start[c + 1]).

## Extra growth of binned shapes, px.
const BIN_MARGIN := 1.0
## Smallest cell size, px: small cells duplicate long walls into many lists. Cells are
## otherwise one ball diameter (+1 px), so ball pairs need only the neighbouring cells.
const MIN_CELL := 8.0

## The shapes binned here (the only ones this grid reads).
var shapes := StaticShapes.new()
## Grid: origin, cell size, columns, rows; the flat cell lists.
var origin := Vector2.ZERO
var cell := MIN_CELL
var inv_cell := 1.0 / MIN_CELL
var cols := 1
var rows := 1
var pin_start := PackedInt32Array()
var pin_items := PackedInt32Array()
## Position and radius of each entry of pin_items, side by side, so the hot loop reads one
## array slot instead of following the index.
var pin_item_pos := PackedVector2Array()
var pin_item_radius := PackedFloat32Array()
var wall_start := PackedInt32Array()
var wall_items := PackedInt32Array()
## Each entry of wall_items' a, b - a, 1 / |b - a|² and radius, side by side (see pins).
var wall_item_a := PackedVector2Array()
var wall_item_ab := PackedVector2Array()
var wall_item_inv := PackedFloat32Array()
var wall_item_radius := PackedFloat32Array()
## Smallest pin or wall radius (the thinnest feature a ball must not tunnel through).
var min_feature := 0.0
## Closest centre distance between two pins whose grown shapes overlap (INF if none):
## two such pins form a notch that is thinner than either pin; see max_travel().
var pin_spacing := INF
var min_pin_radius := INF
## The ball radius the grid was built for; a larger ball forces a rebuild.
var built_ball_radius := 0.0
## False when every ball tests every pin (`all_pins`), the benchmark's brute-force baseline.
var zoned := true
var all_pins := PackedInt32Array()
## Points the grid must also cover: the sweep boxes of the moving shapes (BallWorld sets them).
var kinematic_points := PackedVector2Array()


## Bins every pin and wall for balls up to `ball_radius`.
func build(ball_radius: float, use_zoning := true) -> void:
	built_ball_radius = ball_radius
	zoned = use_zoning
	all_pins.resize(shapes.pin_pos.size())
	for i: int in shapes.pin_pos.size():
		all_pins[i] = i
	var grow: float = ball_radius + BIN_MARGIN
	var max_pin := 0.0
	min_feature = INF
	for r: float in shapes.pin_radius:
		max_pin = maxf(max_pin, r)
		min_feature = minf(min_feature, r)
	for r: float in shapes.wall_radius:
		min_feature = minf(min_feature, r)
	if min_feature == INF:
		min_feature = 0.0
	cell = maxf(MIN_CELL, 2.0 * ball_radius + 1.0)
	inv_cell = 1.0 / cell
	var box := _bounds()
	var pad: float = grow + max_pin + cell
	origin = box.position - Vector2(pad, pad)
	# At least three columns: the ball-ball pass takes "next cell" and "cells below" as two
	# separate runs of the sorted keys, which must not overlap.
	cols = maxi(3, ceili((box.size.x + 2.0 * pad) * inv_cell))
	rows = maxi(1, ceili((box.size.y + 2.0 * pad) * inv_cell))
	_bin_pins(grow)
	pin_item_pos.resize(pin_items.size())
	pin_item_radius.resize(pin_items.size())
	for k: int in pin_items.size():
		pin_item_pos[k] = shapes.pin_pos[pin_items[k]]
		pin_item_radius[k] = shapes.pin_radius[pin_items[k]]
	_bin_walls(grow)
	var n_items: int = wall_items.size()
	wall_item_a.resize(n_items)
	wall_item_ab.resize(n_items)
	wall_item_inv.resize(n_items)
	wall_item_radius.resize(n_items)
	for k: int in n_items:
		var w: int = wall_items[k]
		wall_item_a[k] = shapes.wall_a[w]
		wall_item_ab[k] = shapes.wall_ab[w]
		wall_item_inv[k] = shapes.wall_inv_len2[w]
		wall_item_radius[k] = shapes.wall_radius[w]
	_find_pin_spacing(2.0 * (max_pin + ball_radius))
	shapes.dirty = false


## Longest safe move (px) in one substep for a ball of radius r: a centre that enters a
## shape by less than this never reaches the far side of it. For a lone pin or wall that
## is their radius plus r; where two pins' grown circles overlap, only the notch between
## them (half-thickness sqrt(R² - (s/2)²)) is left to stop the ball.
func max_travel(r: float, share: float) -> float:
	var t: float = min_feature + r
	var half: float = pin_spacing * 0.5
	var grown: float = min_pin_radius + r
	if half < grown:
		t = minf(t, sqrt(grown * grown - half * half))
	return share * maxf(t, 0.1 * r)


func _find_pin_spacing(limit: float) -> void:
	pin_spacing = INF
	min_pin_radius = INF
	for r: float in shapes.pin_radius:
		min_pin_radius = minf(min_pin_radius, r)
	var lim2: float = limit * limit
	for c: int in cols * rows:
		var lo: int = pin_start[c]
		var hi: int = pin_start[c + 1]
		for a: int in range(lo, hi):
			var pa: Vector2 = shapes.pin_pos[pin_items[a]]
			for b: int in range(a + 1, hi):
				var d2: float = pa.distance_squared_to(shapes.pin_pos[pin_items[b]])
				if d2 < lim2:
					pin_spacing = minf(pin_spacing, sqrt(d2))


## Index of the cell holding `p`, clamped to the grid.
func cell_of(p: Vector2) -> int:
	var cx: int = clampi(int((p.x - origin.x) * inv_cell), 0, cols - 1)
	var cy: int = clampi(int((p.y - origin.y) * inv_cell), 0, rows - 1)
	return cy * cols + cx


func _bounds() -> Rect2:
	var have := false
	var box := Rect2()
	var pts := PackedVector2Array()
	pts.append_array(shapes.pin_pos)
	pts.append_array(shapes.wall_a)
	pts.append_array(shapes.wall_b)
	pts.append_array(shapes.hole_pos)
	pts.append_array(shapes.goal_pos)
	pts.append_array(shapes.zone_pos)
	pts.append_array(kinematic_points)
	if shapes.has_ring:
		pts.append(shapes.ring_center - Vector2(shapes.ring_radius, shapes.ring_radius))
		pts.append(shapes.ring_center + Vector2(shapes.ring_radius, shapes.ring_radius))
	for p: Vector2 in pts:
		if have:
			box = box.expand(p)
		else:
			box = Rect2(p, Vector2.ZERO)
			have = true
	var max_wall := 0.0
	for r: float in shapes.wall_radius:
		max_wall = maxf(max_wall, r)
	return box.grow(max_wall)


func _bin_pins(grow: float) -> void:
	var n_cells: int = cols * rows
	var counts := PackedInt32Array()
	counts.resize(n_cells + 1)
	counts.fill(0)
	# Two passes (count, then fill) over the same cell ranges keep the lists flat.
	for pass_i: int in 2:
		var fill := PackedInt32Array()
		if pass_i == 1:
			pin_start = PackedInt32Array()
			pin_start.resize(n_cells + 1)
			var run := 0
			for c: int in n_cells:
				pin_start[c] = run
				run += counts[c]
			pin_start[n_cells] = run
			pin_items = PackedInt32Array()
			pin_items.resize(run)
			fill = pin_start.duplicate()
		for i: int in shapes.pin_pos.size():
			var p: Vector2 = shapes.pin_pos[i]
			var reach: float = shapes.pin_radius[i] + grow
			var x0: int = clampi(floori((p.x - reach - origin.x) * inv_cell), 0, cols - 1)
			var x1: int = clampi(floori((p.x + reach - origin.x) * inv_cell), 0, cols - 1)
			var y0: int = clampi(floori((p.y - reach - origin.y) * inv_cell), 0, rows - 1)
			var y1: int = clampi(floori((p.y + reach - origin.y) * inv_cell), 0, rows - 1)
			for cy: int in range(y0, y1 + 1):
				for cx: int in range(x0, x1 + 1):
					var lo := Vector2(origin.x + cx * cell, origin.y + cy * cell)
					var q := Vector2(clampf(p.x, lo.x, lo.x + cell), clampf(p.y, lo.y, lo.y + cell))
					if q.distance_squared_to(p) > reach * reach:
						continue
					var c: int = cy * cols + cx
					if pass_i == 0:
						counts[c] += 1
					else:
						pin_items[fill[c]] = i
						fill[c] += 1


func _bin_walls(grow: float) -> void:
	var n_cells: int = cols * rows
	var counts := PackedInt32Array()
	counts.resize(n_cells + 1)
	counts.fill(0)
	var half_diag: float = cell * 0.7072
	for pass_i: int in 2:
		var fill := PackedInt32Array()
		if pass_i == 1:
			wall_start = PackedInt32Array()
			wall_start.resize(n_cells + 1)
			var run := 0
			for c: int in n_cells:
				wall_start[c] = run
				run += counts[c]
			wall_start[n_cells] = run
			wall_items = PackedInt32Array()
			wall_items.resize(run)
			fill = wall_start.duplicate()
		for i: int in shapes.wall_a.size():
			if shapes.wall_off[i] != 0:
				continue
			var a: Vector2 = shapes.wall_a[i]
			var b: Vector2 = shapes.wall_b[i]
			var reach: float = shapes.wall_radius[i] + grow
			var x0: int = clampi(
				floori((minf(a.x, b.x) - reach - origin.x) * inv_cell), 0, cols - 1
			)
			var x1: int = clampi(
				floori((maxf(a.x, b.x) + reach - origin.x) * inv_cell), 0, cols - 1
			)
			var y0: int = clampi(
				floori((minf(a.y, b.y) - reach - origin.y) * inv_cell), 0, rows - 1
			)
			var y1: int = clampi(
				floori((maxf(a.y, b.y) + reach - origin.y) * inv_cell), 0, rows - 1
			)
			for cy: int in range(y0, y1 + 1):
				for cx: int in range(x0, x1 + 1):
					var mid := Vector2(origin.x + (cx + 0.5) * cell, origin.y + (cy + 0.5) * cell)
					var q: Vector2 = Geometry2D.get_closest_point_to_segment(mid, a, b)
					var lim: float = reach + half_diag
					if q.distance_squared_to(mid) > lim * lim:
						continue
					var c: int = cy * cols + cx
					if pass_i == 0:
						counts[c] += 1
					else:
						wall_items[fill[c]] = i
						fill[c] += 1
