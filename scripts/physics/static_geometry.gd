extends RefCounted
## Static shapes of a BallWorld (pins, capsule walls, ring, sensors) and the uniform grid
## they are binned into ("pin zoning"). Internal to scripts/physics: BallWorld owns one.
##
## A grid cell lists every pin and wall whose shape, grown by the largest ball radius and a
## margin, touches the cell; so a ball only tests the shapes of the one cell its centre is in.
## Lists are stored flat (CSR): items of cell c are items[start[c] .. start[c + 1]).

## Extra growth of binned shapes, px.
const BIN_MARGIN := 1.0
## Smallest cell size, px: small cells duplicate long walls into many lists. Cells are
## otherwise one ball diameter (+1 px), so ball pairs need only the neighbouring cells.
const MIN_CELL := 8.0
## Sensor kinds (see add_sensor).
const SENSOR_HOLE := 0
const SENSOR_GOAL := 1
const SENSOR_ZONE := 2
## Goals and zones are tracked per ball in one int bit mask each.
const MAX_SENSORS := 31

var pin_pos := PackedVector2Array()
var pin_radius := PackedFloat32Array()
## A tag the pin's owner gives it (-1: none), reported when the pin captures a ball.
var pin_tag := PackedInt32Array()
## 1 for a pin that captures (removes) a ball that touches it.
var pin_captures := PackedByteArray()
## Material: the least horizontal speed (px/s) a ball keeps after touching the pin.
var pin_min_speed_x := PackedFloat64Array()

var wall_a := PackedVector2Array()
var wall_b := PackedVector2Array()
var wall_radius := PackedFloat32Array()
## b - a, and 1 / |b - a|² (0 for a zero-length wall, which acts as a round pin).
var wall_ab := PackedVector2Array()
var wall_inv_len2 := PackedFloat32Array()
## Per wall: 1 while it is switched off (a pachinko gate that is open). An off wall is left
## out of the grid, so the narrow phase never sees it and the hot loop stays unchanged.
var wall_off := PackedByteArray()

var has_ring := false
var ring_center := Vector2.ZERO
var ring_radius := 0.0

## The drain arc: a stretch of the ring (degrees) that removes a ball after drain_bounces
## bounces on it or drain_slide_time seconds of rolling on it.
var has_drain_arc := false
var drain_from := 0.0
var drain_to := 0.0
var drain_bounces := 1
var drain_slide_time := 0.5

var hole_pos := PackedVector2Array()
var hole_radius := PackedFloat32Array()
var goal_pos := PackedVector2Array()
var goal_radius := PackedFloat32Array()
var zone_pos := PackedVector2Array()
var zone_radius := PackedFloat32Array()

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
var dirty := true


## Bins every pin and wall for balls up to `ball_radius`.
func build(ball_radius: float, use_zoning := true) -> void:
	built_ball_radius = ball_radius
	zoned = use_zoning
	all_pins.resize(pin_pos.size())
	for i: int in pin_pos.size():
		all_pins[i] = i
	var grow: float = ball_radius + BIN_MARGIN
	var max_pin := 0.0
	min_feature = INF
	for r: float in pin_radius:
		max_pin = maxf(max_pin, r)
		min_feature = minf(min_feature, r)
	for r: float in wall_radius:
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
		pin_item_pos[k] = pin_pos[pin_items[k]]
		pin_item_radius[k] = pin_radius[pin_items[k]]
	_bin_walls(grow)
	var n_items: int = wall_items.size()
	wall_item_a.resize(n_items)
	wall_item_ab.resize(n_items)
	wall_item_inv.resize(n_items)
	wall_item_radius.resize(n_items)
	for k: int in n_items:
		var w: int = wall_items[k]
		wall_item_a[k] = wall_a[w]
		wall_item_ab[k] = wall_ab[w]
		wall_item_inv[k] = wall_inv_len2[w]
		wall_item_radius[k] = wall_radius[w]
	_find_pin_spacing(2.0 * (max_pin + ball_radius))
	dirty = false


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
	for r: float in pin_radius:
		min_pin_radius = minf(min_pin_radius, r)
	var lim2: float = limit * limit
	for c: int in cols * rows:
		var lo: int = pin_start[c]
		var hi: int = pin_start[c + 1]
		for a: int in range(lo, hi):
			var pa: Vector2 = pin_pos[pin_items[a]]
			for b: int in range(a + 1, hi):
				var d2: float = pa.distance_squared_to(pin_pos[pin_items[b]])
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
	pts.append_array(pin_pos)
	pts.append_array(wall_a)
	pts.append_array(wall_b)
	pts.append_array(hole_pos)
	pts.append_array(goal_pos)
	pts.append_array(zone_pos)
	if has_ring:
		pts.append(ring_center - Vector2(ring_radius, ring_radius))
		pts.append(ring_center + Vector2(ring_radius, ring_radius))
	for p: Vector2 in pts:
		if have:
			box = box.expand(p)
		else:
			box = Rect2(p, Vector2.ZERO)
			have = true
	var max_wall := 0.0
	for r: float in wall_radius:
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
		for i: int in pin_pos.size():
			var p: Vector2 = pin_pos[i]
			var reach: float = pin_radius[i] + grow
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
		for i: int in wall_a.size():
			if wall_off[i] != 0:
				continue
			var a: Vector2 = wall_a[i]
			var b: Vector2 = wall_b[i]
			var reach: float = wall_radius[i] + grow
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


## True when the direction `d` from the ring centre lies in the drain arc (degrees, y down,
## from drain_from clockwise on screen to drain_to).
func in_drain_arc(d: Vector2) -> bool:
	var span: float = fposmod(drain_to - drain_from, 360.0)
	if span == 0.0 and drain_to != drain_from:
		span = 360.0
	return fposmod(rad_to_deg(atan2(d.y, d.x)) - drain_from, 360.0) <= span


## Sets the ring border (BallWorld.set_ring); refuses a non-finite centre or radius <= 0.
func set_ring(center: Vector2, radius: float) -> void:
	if not center.is_finite() or not is_finite(radius) or radius <= 0.0:
		var problem: String = "BallWorld.set_ring: needs a finite centre and radius > 0 (got %s, %s)"
		push_error(problem % [center, radius])
		return
	has_ring = true
	ring_center = center
	ring_radius = radius
	dirty = true


## Makes a ring arc drain (BallWorld.set_drain_arc); refuses bad input with an error.
func set_drain_arc(from_deg: float, to_deg: float, bounces: int, slide_time: float) -> void:
	var finite: bool = is_finite(from_deg) and is_finite(to_deg) and is_finite(slide_time)
	if not finite or bounces < 1 or slide_time < 0.0:
		var problem: String = "BallWorld.set_drain_arc: needs finite angles, bounces >= 1 and"
		problem += " slide_time >= 0 (got %s, %s, %d, %s)"
		push_error(problem % [from_deg, to_deg, bounces, slide_time])
		return
	has_drain_arc = true
	drain_from = from_deg
	drain_to = to_deg
	drain_bounces = bounces
	drain_slide_time = slide_time


## Adds a pin; returns its index, or -1 with an error naming the bad input.
func add_pin(pos: Vector2, radius: float, tag: int, captures: bool, min_speed_x: float) -> int:
	if not pos.is_finite() or not is_finite(radius) or radius < 0.0:
		var problem: String = "BallWorld.add_pin: needs a finite position and radius >= 0 (got %s, %s)"
		push_error(problem % [pos, radius])
		return -1
	if not is_finite(min_speed_x) or min_speed_x < 0.0:
		var problem: String = "BallWorld.add_pin: min_speed_x must be finite and >= 0 (got %s)"
		push_error(problem % min_speed_x)
		return -1
	pin_pos.append(pos)
	pin_radius.append(radius)
	pin_tag.append(tag)
	pin_captures.append(1 if captures else 0)
	pin_min_speed_x.append(min_speed_x)
	dirty = true
	return pin_pos.size() - 1


## Adds a capsule wall; returns its index, or -1 with an error naming the bad input.
func add_wall(a: Vector2, b: Vector2, radius: float) -> int:
	if not a.is_finite() or not b.is_finite() or not is_finite(radius) or radius < 0.0:
		var problem: String = "BallWorld.add_wall: needs finite ends and radius >= 0 (got %s, %s, %s)"
		push_error(problem % [a, b, radius])
		return -1
	var ab: Vector2 = b - a
	var len2: float = ab.length_squared()
	wall_a.append(a)
	wall_b.append(b)
	wall_ab.append(ab)
	wall_inv_len2.append(1.0 / len2 if len2 > 1e-12 else 0.0)
	wall_radius.append(radius)
	wall_off.append(0)
	dirty = true
	return wall_a.size() - 1


## Switches wall `index` on or off (see BallWorld.set_wall_enabled); false for a bad index.
func set_wall_enabled(index: int, enabled: bool) -> bool:
	if index < 0 or index >= wall_a.size():
		push_error("BallWorld.set_wall_enabled: no wall %d (%d walls)" % [index, wall_a.size()])
		return false
	var off := 0 if enabled else 1
	if wall_off[index] != off:
		wall_off[index] = off
		dirty = true
	return true


## Adds a sensor circle of `kind` (SENSOR_HOLE, SENSOR_GOAL, SENSOR_ZONE); returns its index
## among its kind, or -1 with an error. Goals and zones are tracked in one bit mask per
## ball, so there are at most MAX_SENSORS of each.
func add_sensor(kind: int, center: Vector2, radius: float) -> int:
	var what: String = ["add_hole", "add_goal", "add_zone"][kind]
	if not center.is_finite() or not is_finite(radius) or radius <= 0.0:
		var problem: String = "BallWorld.%s: needs a finite centre and radius > 0 (got %s, %s)"
		push_error(problem % [what, center, radius])
		return -1
	var centres: Array[PackedVector2Array] = [hole_pos, goal_pos, zone_pos]
	if kind != SENSOR_HOLE and centres[kind].size() >= MAX_SENSORS:
		push_error("BallWorld.%s: at most %d per world" % [what, MAX_SENSORS])
		return -1
	match kind:
		SENSOR_HOLE:
			hole_pos.append(center)
			hole_radius.append(radius)
			return hole_pos.size() - 1
		SENSOR_GOAL:
			goal_pos.append(center)
			goal_radius.append(radius)
			return goal_pos.size() - 1
	zone_pos.append(center)
	zone_radius.append(radius)
	return zone_pos.size() - 1
