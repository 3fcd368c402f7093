class_name Windmills
extends RefCounted
## The kinematic shapes of a BallWorld: windmills (風車), wheels of capsule blades turning
## about a pin. The world moves them itself each step; balls never push them through space,
## only, on a free wheel, change how fast it turns. Internal to scripts/physics: use
## BallWorld.add_windmill().
##
## A wheel's pose during step n is a pure function of its state at the step's start: blade k
## of wheel m points at angle[m] + omega[m] * t + k * TAU / blades[m] at time t into the
## step. A driven wheel keeps its omega; a free wheel gathers the angular impulse of every
## ball that touched it during the step (summed in ball order, so any thread count gives
## the same result), then loses `friction` rad/s² of speed. omega is capped so that no
## blade tip outruns the fastest ball (BallMover's swept test relies on it).
##
## Like the static shapes, the wheels are binned into the world's grid: a cell lists every
## wheel whose sweep circle (blade length + blade radius), grown by the largest ball radius
## and `margin`, touches it, so a ball tests only the wheels it can reach this step.

## Mass of one blade in balls: sets a free wheel's moment of inertia (blades * mass * L² / 3),
## so how much one hit spins it up.
const BLADE_MASS := 3.0
## Bits of a wheel index in the binning keys (at most 2^20 wheels).
const WHEEL_BITS := 20

var center := PackedVector2Array()
var blades := PackedInt32Array()
## Blade length from the pin to the middle of the tip cap (px), and blade radius (px).
var length := PackedFloat64Array()
var blade_radius := PackedFloat64Array()
## length + blade_radius: the circle a wheel sweeps.
var reach := PackedFloat64Array()
## The pose at the start of the current step: angle of blade 0 (rad, y down, so positive
## turns clockwise on screen), angular speed (rad/s).
var angle := PackedFloat64Array()
var omega := PackedFloat64Array()
## 1 for a free wheel (spun by balls, slowed by friction), 0 for a driven one.
var free := PackedByteArray()
## A free wheel's friction (rad/s²) and 1 / moment of inertia (in ball masses · px²).
var friction := PackedFloat64Array()
## Material: the least horizontal speed (px/s) a ball keeps after touching a blade, so none
## balances in the V of two blades (as the pins' min_speed_x).
var min_speed_x := PackedFloat64Array()
var inv_inertia := PackedFloat64Array()
## The grid: wheels of cell c are items[start[c] .. start[c + 1]) (empty until bin()).
var start := PackedInt32Array()
var items := PackedInt32Array()
## The margin the wheels were binned with (px): a ball that may travel farther in one step
## tests every wheel instead of its cell's.
var margin := 0.0
## Thinnest blade radius (INF with no wheels).
var min_blade_radius := INF


func count() -> int:
	return center.size()


## Adds a wheel; returns its index, or -1 with an error naming the bad input. `speed` is
## rad/s (a driven wheel turns at it; a free one starts at it), `friction` rad/s².
func add(
	at: Vector2,
	blade_count: int,
	blade_length: float,
	radius: float,
	speed: float,
	spins_free: bool,
	slowing: float,
	least_speed_x: float
) -> int:
	var numbers_ok: bool = (
		at.is_finite()
		and is_finite(blade_length)
		and is_finite(radius)
		and is_finite(speed)
		and is_finite(slowing)
		and is_finite(least_speed_x)
		and least_speed_x >= 0.0
	)
	if not numbers_ok or blade_count < 1 or blade_length <= 0.0 or radius <= 0.0 or slowing < 0.0:
		var problem: String = "BallWorld.add_windmill: needs a finite centre and speed, friction and"
		problem += " min_speed_x >= 0, at least one blade, length > 0 and blade radius > 0"
		problem += " (got %s, %d, %s, %s, %s, %s, %s)"
		push_error(problem % [at, blade_count, blade_length, radius, speed, slowing, least_speed_x])
		return -1
	center.append(at)
	blades.append(blade_count)
	length.append(blade_length)
	blade_radius.append(radius)
	reach.append(blade_length + radius)
	angle.append(0.0)
	omega.append(speed)
	free.append(1 if spins_free else 0)
	friction.append(slowing)
	min_speed_x.append(least_speed_x)
	inv_inertia.append(3.0 / (blade_count * BLADE_MASS * blade_length * blade_length))
	min_blade_radius = minf(min_blade_radius, radius)
	return center.size() - 1


## The points the grid must cover (each wheel's sweep box corners).
func bounds_points() -> PackedVector2Array:
	var pts := PackedVector2Array()
	for m: int in center.size():
		var r: float = reach[m]
		pts.append(center[m] - Vector2(r, r))
		pts.append(center[m] + Vector2(r, r))
	return pts


## Bins the wheels into the grid of `origin`, `cell`, `cols` × `rows`, each grown by `grow`
## (largest ball radius + margin) plus `travel_margin`.
func bin(
	origin: Vector2, cell: float, cols: int, rows: int, grow: float, travel_margin: float
) -> void:
	margin = travel_margin
	var n_cells: int = cols * rows
	# (cell << 20 | wheel) per cell a wheel reaches, sorted: the cells' lists in order.
	var keys := PackedInt64Array()
	var inv: float = 1.0 / cell
	for m: int in center.size():
		var p: Vector2 = center[m]
		var r: float = reach[m] + grow + travel_margin
		var x0: int = clampi(floori((p.x - r - origin.x) * inv), 0, cols - 1)
		var x1: int = clampi(floori((p.x + r - origin.x) * inv), 0, cols - 1)
		var y0: int = clampi(floori((p.y - r - origin.y) * inv), 0, rows - 1)
		var y1: int = clampi(floori((p.y + r - origin.y) * inv), 0, rows - 1)
		for cy: int in range(y0, y1 + 1):
			for cx: int in range(x0, x1 + 1):
				var lo := Vector2(origin.x + cx * cell, origin.y + cy * cell)
				var q := Vector2(clampf(p.x, lo.x, lo.x + cell), clampf(p.y, lo.y, lo.y + cell))
				if q.distance_squared_to(p) <= r * r:
					keys.append((cy * cols + cx) << WHEEL_BITS | m)
	keys.sort()
	start.resize(n_cells + 1)
	items.resize(keys.size())
	var k := 0
	for c: int in n_cells:
		start[c] = k
		while k < keys.size() and (keys[k] >> WHEEL_BITS) == c:
			items[k] = keys[k] & ((1 << WHEEL_BITS) - 1)
			k += 1
	start[n_cells] = k


## Ends a step of `dt` s: every wheel turns by omega * dt, then each free wheel takes the
## impulses of the step (`pushed`: wheel index, change of omega, in ball order), loses its
## friction's worth of speed and is held to `max_tip_speed` at its blade tips.
func advance(
	dt: float, pushed_index: PackedInt32Array, pushed: PackedFloat64Array, max_tip_speed: float
) -> void:
	for m: int in center.size():
		angle[m] = fposmod(angle[m] + omega[m] * dt, TAU)
	for e: int in pushed.size():
		var m: int = pushed_index[e]
		omega[m] += pushed[e]
	for m: int in center.size():
		var w: float = omega[m]
		if free[m] != 0:
			w = move_toward(w, 0.0, friction[m] * dt)
		var cap: float = max_tip_speed / reach[m]
		omega[m] = clampf(w, -cap, cap)
