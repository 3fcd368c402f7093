extends RefCounted
## The phases of one BallWorld step, as static functions over the ball store and the static
## geometry. Internal to scripts/physics. Hot loops: typed locals, flat loops, math inline.
##
## Phases: gravity → ball-ball contacts (velocity impulses now, separation as a displacement
## swept with the motion) → motion (BallMotion: rolling friction and the speed cap, then the
## static shapes in substeps short enough that no ball can cross a pin, a wall or the ring)
## → sensors.

enum Ev { PIN_HIT, WALL_HIT, RING_HIT, POCKETED, DRAINED, HOLE, GOAL, GOAL_LEFT, ZONE }

const BallStore := preload("res://scripts/physics/ball_store.gd")
const StaticGeometry := preload("res://scripts/physics/static_geometry.gd")

## Contact key of the ring (pins are index + 1, walls -(index + 1)).
const RING_KEY := 0x3fffffff
## A substep moves at most this share of the thinnest (ball + feature) radius: a centre
## that enters a shape is then never past the shape's middle, so it leaves on its own side.
const TRAVEL_SHARE := 0.5
## A support counts when its normal is within about 60° of the line between two balls.
const SUPPORT_COS := 0.5
## Share of a ball-ball overlap each ball moves apart per step.
const PUSH_SHARE := 0.4
## Overlap (px) two balls keep rather than being pushed apart: a resting pair stays in
## touch, so each step's contact takes gravity's approach away. Pushed fully apart, it
## would fall back in every step and never settle.
const CONTACT_SLOP := 0.05
## Safety bound on substeps for one ball in one step.
const MAX_SUBSTEPS := 1024
## Sort keys of the ball-ball broad phase: cell << SORT_SHIFT | ball index.
const SORT_SHIFT := 21
const SORT_MASK := (1 << 21) - 1
## Larger than any sort key.
const SORT_SENTINEL := 0x7fffffffffffffff
## Distances below this count as zero (px).
const EPS := 1e-6


## Gravity, as one native translate of every velocity. Sleeping balls get it too; the
## motion phase zeroes them again. The motion phase applies rolling friction and the speed
## cap as it reads each ball, where they cost one expression each.
static func apply_gravity(b: BallStore, gravity: Vector2, dt: float) -> void:
	b.vel = Transform2D(Vector2.RIGHT, Vector2.DOWN, gravity * dt) * b.vel


## Ball-ball contacts between equal masses. Balls are sorted by grid cell with one native
## sort of (cell << SORT_SHIFT | ball) keys; cells are at least a ball diameter, so a ball
## only meets balls of its own cell, the next cell and the three cells below, and those are
## two runs of the sorted keys. The run below is found by a pointer that only moves forward,
## as cells only grow along the sorted keys. Wrapped rows add candidates but never miss any.
## A sleeping ball acts as a fixed ball unless hit faster than `wake_speed`, which wakes it;
## contacts slower than `threshold` do not bounce. Against a held ball, the approach this
## step's gravity (`gravity_dt`) gave does not count toward the threshold, as on a static
## shape: otherwise a ball lying on a held ball would bounce on it for ever.
static func collide_balls(
	b: BallStore,
	g: StaticGeometry,
	restitution: float,
	threshold: float,
	wake_speed: float,
	gravity_dt: Vector2
) -> void:
	var n: int = b.ids.size()
	var push: PackedVector2Array = b.push
	push.fill(Vector2.ZERO)
	var touching: PackedByteArray = b.touching
	touching.resize(n)
	touching.fill(0)
	if n < 2:
		b.push = push
		b.touching = touching
		return
	var pos: PackedVector2Array = b.pos
	var vel: PackedVector2Array = b.vel
	var rad: PackedFloat32Array = b.radius
	var asleep: PackedByteArray = b.asleep
	var rest: PackedFloat32Array = b.rest
	var sup_static: PackedVector2Array = b.support_static
	var sup_static2: PackedVector2Array = b.support_static2
	var sup_prev: PackedVector2Array = b.support_ball
	var sup_next := PackedVector2Array()
	sup_next.resize(n)
	var cols: int = g.cols
	var origin: Vector2 = g.origin
	var last_cell := Vector2i(cols - 1, g.rows - 1)
	var inv: float = g.inv_cell
	var keys: PackedInt64Array = b.sort_keys
	keys.resize(n + 1)
	for i: int in n:
		var p: Vector2 = pos[i]
		var ci: Vector2i = Vector2i((p - origin) * inv).clamp(Vector2i.ZERO, last_cell)
		keys[i] = ((ci.y * cols + ci.x) << SORT_SHIFT) | i
	# A sentinel past every key ends each scan below without a bounds test.
	keys[n] = SORT_SENTINEL
	keys.sort()
	var mask: int = SORT_MASK
	var cell_bits: int = ~SORT_MASK
	# Key offsets from a cell's first key: two cells on, and the three cells below.
	var next_off: int = 2 << SORT_SHIFT
	var below_off: int = (cols - 1) << SORT_SHIFT
	var past_below_off: int = (cols + 2) << SORT_SHIFT
	var below := 0
	for k: int in n:
		var key: int = keys[k]
		var cell_key: int = key & cell_bits
		# Same cell (later balls) and the next cell.
		var end_same: int = k + 1
		var next_cell: int = cell_key + next_off
		while keys[end_same] < next_cell:
			end_same += 1
		# The three cells below.
		var first_below: int = cell_key + below_off
		while keys[below] < first_below:
			below += 1
		var end_below: int = below
		var past_below: int = cell_key + past_below_off
		while keys[end_below] < past_below:
			end_below += 1
		if end_same == k + 1 and end_below == below:
			continue  # a lone ball (most of a flowing board): nothing to read
		var i: int = key & mask
		var pi: Vector2 = pos[i]
		var ri: float = rad[i]
		var sleep_i: bool = asleep[i] != 0
		for run: int in 2:
			var m0: int = k + 1 if run == 0 else below
			var m1: int = end_same if run == 0 else end_below
			for m: int in range(m0, m1):
				var j: int = keys[m] & mask
				var d: Vector2 = pos[j] - pi
				var rr: float = ri + rad[j]
				var d2: float = d.length_squared()
				if d2 >= rr * rr:
					continue
				touching[i] = 1
				touching[j] = 1
				var sleep_j: bool = asleep[j] != 0
				if sleep_i and sleep_j:
					continue
				var dist: float = sqrt(d2)
				var nrm := Vector2(1.0, 0.0)
				if dist > EPS:
					nrm = d / dist
				var vi: Vector2 = Vector2.ZERO if sleep_i else vel[i]
				var vj: Vector2 = Vector2.ZERO if sleep_j else vel[j]
				var vn: float = (vj - vi).dot(nrm)
				# A real hit wakes the sleeper, which then answers as a free ball. A sleeper's
				# velocity holds just this step's gravity, which the other ball got too: a
				# ball merely pressing on it under gravity does not count as a hit.
				if (sleep_i or sleep_j) and (vel[i] - vel[j]).dot(nrm) > wake_speed:
					if sleep_i:
						asleep[i] = 0
						rest[i] = 0.0
						sleep_i = false
						vi = vel[i]
					else:
						asleep[j] = 0
						rest[j] = 0.0
						sleep_j = false
						vj = vel[j]
					vn = (vj - vi).dot(nrm)
				# A ball held from behind (asleep, or pressed on a support that faces the
				# other ball) does not give way: the other takes the whole response.
				var fixed_i: bool = (
					sleep_i
					or sup_static[i].dot(nrm) > SUPPORT_COS
					or sup_static2[i].dot(nrm) > SUPPORT_COS
					or sup_prev[i].dot(nrm) > SUPPORT_COS
				)
				var fixed_j: bool = (
					sleep_j
					or sup_static[j].dot(nrm) < -SUPPORT_COS
					or sup_static2[j].dot(nrm) < -SUPPORT_COS
					or sup_prev[j].dot(nrm) < -SUPPORT_COS
				)
				var s: Vector2 = nrm * (maxf(rr - dist - CONTACT_SLOP, 0.0) * PUSH_SHARE)
				if fixed_j and not fixed_i:
					# The support cancels j's own motion into it: only i's speed counts.
					vn = -vi.dot(nrm)
					if vn < 0.0:
						var hit: float = -vn - maxf(gravity_dt.dot(nrm), 0.0)
						var e: float = restitution if hit > threshold else 0.0
						vel[i] = vi + nrm * ((1.0 + e) * vn)
					push[i] -= s * 2.0
					sup_next[i] = -nrm
				elif fixed_i and not fixed_j:
					vn = vj.dot(nrm)
					if vn < 0.0:
						var hit: float = -vn - maxf(-gravity_dt.dot(nrm), 0.0)
						var e: float = restitution if hit > threshold else 0.0
						vel[j] = vj - nrm * ((1.0 + e) * vn)
					push[j] += s * 2.0
					sup_next[j] = nrm
				elif not (sleep_i or sleep_j):
					if vn < 0.0:
						var e: float = restitution if -vn > threshold else 0.0
						var imp: Vector2 = nrm * (-(1.0 + e) * vn * 0.5)
						vel[i] = vi - imp
						vel[j] = vj + imp
					push[i] -= s
					push[j] += s
	b.vel = vel
	b.push = push
	b.touching = touching
	b.support_ball = sup_next
	b.asleep = asleep
	b.rest = rest


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
