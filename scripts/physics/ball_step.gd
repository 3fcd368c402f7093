extends RefCounted
## The phases of one BallWorld step, as static functions over the ball store and the static
## geometry. Internal to scripts/physics. Hot loops: typed locals, flat loops, math inline.
##
## Phases: forces (gravity, rolling friction, speed cap) → ball-ball contacts (velocity
## impulses now, separation as a displacement swept with the motion) → motion against static
## shapes in substeps short enough that no ball can cross a pin, a wall or the ring → sensors.

enum Ev { PIN_HIT, WALL_HIT, RING_HIT, POCKETED, DRAINED, HOLE, GOAL, GOAL_LEFT, ZONE }

const BallStore := preload("res://scripts/physics/ball_store.gd")
const StaticGeometry := preload("res://scripts/physics/static_geometry.gd")

## Contact key of the ring (pins are index + 1, walls -(index + 1)).
const RING_KEY := 0x3fffffff
## A substep moves at most this share of the thinnest (ball + feature) radius: a centre
## that enters a shape is then never past the shape's middle, so it leaves on its own side.
const TRAVEL_SHARE := 0.5
## Share of a ball-ball overlap each ball moves apart per step.
const PUSH_SHARE := 0.4
## Safety bound on substeps for one ball in one step.
const MAX_SUBSTEPS := 1024
## Sort keys of the ball-ball broad phase: cell << SORT_SHIFT | ball index.
const SORT_SHIFT := 21
const SORT_MASK := (1 << 21) - 1
## Distances below this count as zero (px).
const EPS := 1e-6


## Gravity, per-axis rolling friction (never reverses a velocity), then the speed cap.
static func apply_forces(
	b: BallStore, gravity: Vector2, friction: Vector2, max_speed: float, dt: float
) -> void:
	var vel: PackedVector2Array = b.vel
	var gdt: Vector2 = gravity * dt
	var fx: float = maxf(friction.x, 0.0) * dt
	var fy: float = maxf(friction.y, 0.0) * dt
	var has_friction: bool = fx > 0.0 or fy > 0.0
	var cap2: float = max_speed * max_speed
	for i: int in vel.size():
		var v: Vector2 = vel[i] + gdt
		if has_friction:
			if absf(v.x) <= fx:
				v.x = 0.0
			else:
				v.x -= fx if v.x > 0.0 else -fx
			if absf(v.y) <= fy:
				v.y = 0.0
			else:
				v.y -= fy if v.y > 0.0 else -fy
		var s2: float = v.length_squared()
		if s2 > cap2:
			v *= max_speed / sqrt(s2)
		vel[i] = v
	b.vel = vel


## Ball-ball contacts between equal masses: balls are sorted into grid cells (counting
## sort), each pair is tested once, approaching pairs exchange a normal impulse.
static func collide_balls(
	b: BallStore, g: StaticGeometry, restitution: float, threshold: float
) -> void:
	var n: int = b.ids.size()
	var push: PackedVector2Array = b.push
	push.fill(Vector2.ZERO)
	if n < 2:
		b.push = push
		return
	var pos: PackedVector2Array = b.pos
	var vel: PackedVector2Array = b.vel
	var rad: PackedFloat32Array = b.radius
	var cols: int = g.cols
	var rows: int = g.rows
	var ox: float = g.origin.x
	var oy: float = g.origin.y
	var inv: float = g.inv_cell
	var n_cells: int = cols * rows
	# Sort balls by cell with one native sort of (cell << 21 | ball) keys; then each
	# occupied cell's balls are keys[start[c] .. stop[c]). Only occupied cells are touched.
	var keys: PackedInt64Array = b.sort_keys
	keys.resize(n)
	for i: int in n:
		var p: Vector2 = pos[i]
		var cx: int = clampi(int((p.x - ox) * inv), 0, cols - 1)
		var cy: int = clampi(int((p.y - oy) * inv), 0, rows - 1)
		keys[i] = ((cy * cols + cx) << SORT_SHIFT) | i
	keys.sort()
	var start: PackedInt32Array = b.sort_start
	var stop: PackedInt32Array = b.sort_stop
	var order: PackedInt32Array = b.sort_order
	var cell_of: PackedInt32Array = b.sort_cell
	if start.size() != n_cells:
		start.resize(n_cells)
		stop.resize(n_cells)
	start.fill(-1)
	order.resize(n)
	cell_of.resize(n)
	var prev := -1
	for k: int in n:
		var key: int = keys[k]
		var c: int = key >> SORT_SHIFT
		order[k] = key & SORT_MASK
		cell_of[k] = c
		if c != prev:
			start[c] = k
			if prev >= 0:
				stop[prev] = k
			prev = c
	stop[prev] = n
	for k: int in n:
		var i: int = order[k]
		var c: int = cell_of[k]
		var cx: int = c % cols
		var cy: int = c / cols
		var pi: Vector2 = pos[i]
		var ri: float = rad[i]
		# Same cell after this ball, then the cell to the right: one contiguous run.
		var hi_same: int = stop[c]
		if cx < cols - 1 and start[c + 1] >= 0:
			hi_same = stop[c + 1]
		# The three cells below are consecutive, so their balls are one run too.
		var lo_below := -1
		var hi_below := 0
		if cy < rows - 1:
			var b0: int = c + cols - 1 if cx > 0 else c + cols
			var b1: int = c + cols + 1 if cx < cols - 1 else c + cols
			for cc: int in range(b0, b1 + 1):
				var sc: int = start[cc]
				if sc >= 0:
					if lo_below < 0:
						lo_below = sc
					hi_below = stop[cc]
		if lo_below < 0:
			lo_below = 0
			hi_below = 0
		for run: int in 2:
			var m0: int = k + 1 if run == 0 else lo_below
			var m1: int = hi_same if run == 0 else hi_below
			for m: int in range(m0, m1):
				var j: int = order[m]
				var d: Vector2 = pos[j] - pi
				var rr: float = ri + rad[j]
				var d2: float = d.x * d.x + d.y * d.y
				if d2 >= rr * rr:
					continue
				var dist: float = sqrt(d2)
				var nrm := Vector2(1.0, 0.0)
				if dist > EPS:
					nrm = d / dist
				var vi: Vector2 = vel[i]
				var vj: Vector2 = vel[j]
				var vn: float = (vj - vi).dot(nrm)
				if vn < 0.0:
					var e: float = restitution if -vn > threshold else 0.0
					var imp: Vector2 = nrm * (-(1.0 + e) * vn * 0.5)
					vel[i] = vi - imp
					vel[j] = vj + imp
				var s: Vector2 = nrm * ((rr - dist) * PUSH_SHARE)
				push[i] -= s
				push[j] += s
	b.vel = vel
	b.push = push


## Velocity after a bouncing contact: restitution on the normal, friction on the tangent.
static func bounce(v: Vector2, nrm: Vector2, vn: float, e: float, keep_t: float) -> Vector2:
	return (v - nrm * vn) * keep_t - nrm * (vn * e)


## Velocity after a sliding contact (a persisting or gentle one): the normal speed is
## removed, except the part that only comes from the surface curving under a moving ball
## (capped by the curvature `curv` = substep time / radius of curvature). That part turns
## into tangential speed, so riding the ring or rolling round a cap loses nothing, while a
## push from gravity or other balls is never turned into speed.
static func slide(v: Vector2, nrm: Vector2, vn: float, gn_dt: float, curv: float) -> Vector2:
	var vt: Vector2 = v - nrm * vn
	if curv <= 0.0:
		return vt
	var t2: float = vt.length_squared()
	if t2 <= EPS:
		return vt
	var c: float = maxf(minf(vn - minf(gn_dt, 0.0), 0.0), -1.5 * t2 * curv)
	return vt * sqrt((t2 + c * c) / t2)


## How long ago (0..h seconds) a ball at offset `d` from a round surface's centre, moving at
## `v`, was exactly `lim` away: used to bounce with the normal at the moment of impact, not
## the normal of the overlapped position. `inside` is true for the ring (ball within it).
static func back_off(d: Vector2, v: Vector2, lim: float, h: float, inside: bool) -> float:
	var vv: float = v.length_squared()
	if vv <= EPS:
		return 0.0
	var dv: float = d.dot(v)
	var disc: float = dv * dv - vv * (d.length_squared() - lim * lim)
	if disc < 0.0:
		return 0.0
	var root: float = sqrt(disc)
	var s: float = (dv - root) / vv if inside else (dv + root) / vv
	return clampf(s, 0.0, h)
