extends RefCounted
## Ball–ball contacts between equal masses: the broad phase finds the touching pairs, the
## solve answers them. Internal to scripts/physics; BallWorld owns one.
##
## Broad phase: each ball gets a key (cell << SORT_SHIFT | ball) and one native sort puts
## the balls in cell order. Cells are at least a ball diameter, so a ball only meets balls
## of its own cell, the next cell and the three cells below: two runs of the sorted keys.
## The run below is found by a pointer that only moves forward, as cells only grow along
## the keys. Wrapped rows add candidates but never miss any. Binning and the pair search
## run in lanes (BallLanes); each lane lists its pairs in key order, so the list is the
## same for any number of threads.
##
## Solve: one pass over the pairs in that order (it is order-dependent: a ball's new
## velocity feeds its next pair), velocity impulses now and separation as a displacement
## (`push`) that the motion stage sweeps with the ball's own travel.

const BallStore := preload("res://scripts/physics/ball_store.gd")
const StaticGeometry := preload("res://scripts/physics/static_geometry.gd")
const BallLanes := preload("res://scripts/physics/ball_lanes.gd")

## Sort keys of the broad phase: cell << SORT_SHIFT | ball index.
const SORT_SHIFT := 21
const SORT_MASK := (1 << 21) - 1
## Larger than any sort key: it ends each scan without a bounds test.
const SORT_SENTINEL := 0x7fffffffffffffff
## A support counts when its normal is within about 60° of the line between two balls.
const SUPPORT_COS := 0.5
## Share of a ball-ball overlap each ball moves apart per step.
const PUSH_SHARE := 0.4
## Overlap (px) two balls keep rather than being pushed apart: a resting pair stays in
## touch, so each step's contact takes gravity's approach away. Pushed fully apart, it
## would fall back in every step and never settle.
const CONTACT_SLOP := 0.05
## Distances below this count as zero (px).
const EPS := 1e-6

## Touching pairs found by each lane, as (i, j) slot pairs in key order.
var lane_pairs: Array[PackedInt32Array] = []

var _keys := PackedInt64Array()
var _pos := PackedVector2Array()
var _rad := PackedFloat32Array()
var _origin := Vector2.ZERO
var _inv_cell := 1.0
var _cols := 1
var _last_cell := Vector2i.ZERO
# The solve's view of the balls and its constants (set by solve()).
var _vel := PackedVector2Array()
var _push := PackedVector2Array()
var _touching := PackedByteArray()
var _asleep := PackedByteArray()
var _rest := PackedFloat32Array()
var _sup_a := PackedVector2Array()
var _sup_b := PackedVector2Array()
var _sup_prev := PackedVector2Array()
var _sup_next := PackedVector2Array()
var _restitution := 0.0
var _threshold := 0.0
var _wake_speed := 0.0
var _gravity_dt := Vector2.ZERO


## Broad phase: lists every touching pair of balls in lane_pairs.
func find_pairs(b: BallStore, g: StaticGeometry, lanes: BallLanes) -> void:
	var n: int = b.ids.size()
	while lane_pairs.size() < lanes.lanes_for(n):
		lane_pairs.append(PackedInt32Array())
	for pairs: PackedInt32Array in lane_pairs:
		pairs.resize(0)
	if n < 2:
		return
	_pos = b.pos
	_rad = b.radius
	_origin = g.origin
	_inv_cell = g.inv_cell
	_cols = g.cols
	_last_cell = Vector2i(g.cols - 1, g.rows - 1)
	# The motion stage keyed every ball it moved; bin them all only after a change.
	if not b.keys_valid:
		b.own_buffers()
		_keys = b.cell_keys
		lanes.run(_bin_range, n)
		b.keys_valid = true
	_keys = b.cell_keys.duplicate()
	_keys.append(SORT_SENTINEL)
	_keys.sort()
	lanes.run(_find_in_range, n)


## Solve: answers every pair lane_pairs holds. A sleeping ball acts as a fixed ball unless
## hit faster than `wake_speed`, which wakes it; contacts slower than `threshold` do not
## bounce. Against a held ball, the approach this step's gravity (`gravity_dt`) gave does
## not count toward the threshold, as on a static shape: otherwise a ball lying on a held
## ball would bounce on it for ever.
func solve(
	b: BallStore, restitution: float, threshold: float, wake_speed: float, gravity_dt: Vector2
) -> void:
	var n: int = b.ids.size()
	b.push.fill(Vector2.ZERO)
	b.touching.resize(n)
	b.touching.fill(0)
	_sup_next = PackedVector2Array()
	_sup_next.resize(n)
	_vel = b.vel
	_push = b.push
	_touching = b.touching
	_asleep = b.asleep
	_rest = b.rest
	_sup_a = b.support_static
	_sup_b = b.support_static2
	_sup_prev = b.support_ball
	_restitution = restitution
	_threshold = threshold
	_wake_speed = wake_speed
	_gravity_dt = gravity_dt
	for pairs: PackedInt32Array in lane_pairs:
		_solve_pairs(pairs)
	b.support_ball = _sup_next


func _bin_range(_lane: int, from: int, to: int) -> void:
	var keys: PackedInt64Array = _keys
	var pos: PackedVector2Array = _pos
	for i: int in range(from, to):
		var ci: Vector2i = Vector2i((pos[i] - _origin) * _inv_cell).clamp(Vector2i.ZERO, _last_cell)
		keys[i] = ((ci.y * _cols + ci.x) << SORT_SHIFT) | i


func _find_in_range(lane: int, from: int, to: int) -> void:
	var keys: PackedInt64Array = _keys
	var pos: PackedVector2Array = _pos
	var rad: PackedFloat32Array = _rad
	var out: PackedInt32Array = lane_pairs[lane]
	var mask: int = SORT_MASK
	var cell_bits: int = ~SORT_MASK
	# Key offsets from a cell's first key: two cells on, and the three cells below.
	var next_off: int = 2 << SORT_SHIFT
	var below_off: int = (_cols - 1) << SORT_SHIFT
	var past_below_off: int = (_cols + 2) << SORT_SHIFT
	var below: int = keys.bsearch((keys[from] & cell_bits) + below_off)
	for k: int in range(from, to):
		var cell_key: int = keys[k] & cell_bits
		var end_same: int = k + 1
		var next_cell: int = cell_key + next_off
		while keys[end_same] < next_cell:
			end_same += 1
		var first_below: int = cell_key + below_off
		while keys[below] < first_below:
			below += 1
		var end_below: int = below
		var past_below: int = cell_key + past_below_off
		while keys[end_below] < past_below:
			end_below += 1
		if end_same == k + 1 and end_below == below:
			continue  # a lone ball (most of a flowing board): nothing to read
		var i: int = keys[k] & mask
		var pi: Vector2 = pos[i]
		var ri: float = rad[i]
		for run: int in 2:
			for m: int in range(k + 1 if run == 0 else below, end_same if run == 0 else end_below):
				var j: int = keys[m] & mask
				var rr: float = ri + rad[j]
				if pi.distance_squared_to(pos[j]) < rr * rr:
					out.append(i)
					out.append(j)


## Answers the touching pairs (i, j) of one lane's list in order. Each pair is written out
## in the loop (a call per pair costs about as much as the work), and skipped when both
## balls sleep.
func _solve_pairs(pairs: PackedInt32Array) -> void:
	for m: int in range(0, pairs.size(), 2):
		var i: int = pairs[m]
		var j: int = pairs[m + 1]
		_touching[i] = 1
		_touching[j] = 1
		if _asleep[i] != 0 and _asleep[j] != 0:
			continue
		var d: Vector2 = _pos[j] - _pos[i]
		var dist: float = sqrt(d.length_squared())
		var nrm := Vector2(1.0, 0.0)
		if dist > EPS:
			nrm = d / dist
		var sleep_i: bool = _asleep[i] != 0
		var sleep_j: bool = _asleep[j] != 0
		# A real hit wakes the sleeper, which then answers as a free ball. A sleeper's velocity
		# holds just this step's gravity, which the other ball got too: a ball merely pressing
		# on it under gravity does not count as a hit.
		if (sleep_i or sleep_j) and (_vel[i] - _vel[j]).dot(nrm) > _wake_speed:
			var woken: int = i if sleep_i else j
			_asleep[woken] = 0
			_rest[woken] = 0.0
			sleep_i = _asleep[i] != 0
			sleep_j = _asleep[j] != 0
		var vi: Vector2 = Vector2.ZERO if sleep_i else _vel[i]
		var vj: Vector2 = Vector2.ZERO if sleep_j else _vel[j]
		# A ball held from behind (asleep, or pressed last step on a static shape or a held
		# ball that faces the other ball) does not give way: the other takes the whole response.
		var fixed_i: bool = (
			sleep_i
			or _sup_a[i].dot(nrm) > SUPPORT_COS
			or _sup_b[i].dot(nrm) > SUPPORT_COS
			or _sup_prev[i].dot(nrm) > SUPPORT_COS
		)
		var fixed_j: bool = (
			sleep_j
			or _sup_a[j].dot(nrm) < -SUPPORT_COS
			or _sup_b[j].dot(nrm) < -SUPPORT_COS
			or _sup_prev[j].dot(nrm) < -SUPPORT_COS
		)
		var s: Vector2 = nrm * (maxf(_rad[i] + _rad[j] - dist - CONTACT_SLOP, 0.0) * PUSH_SHARE)
		if fixed_j and not fixed_i:
			# The support cancels j's own motion into it: only i's speed counts.
			_bounce_off_held(i, vi, -nrm)
			_push[i] -= s * 2.0
			_sup_next[i] = -nrm
		elif fixed_i and not fixed_j:
			_bounce_off_held(j, vj, nrm)
			_push[j] += s * 2.0
			_sup_next[j] = nrm
		elif not (sleep_i or sleep_j):
			var vn: float = (vj - vi).dot(nrm)
			if vn < 0.0:
				var e: float = _restitution if -vn > _threshold else 0.0
				var imp: Vector2 = nrm * (-(1.0 + e) * vn * 0.5)
				_vel[i] = vi - imp
				_vel[j] = vj + imp
			_push[i] -= s
			_push[j] += s


## Ball `i` (velocity `v`) against a ball that does not give way, along `nrm` (pointing
## from the held ball to `i`).
func _bounce_off_held(i: int, v: Vector2, nrm: Vector2) -> void:
	var vn: float = v.dot(nrm)
	if vn >= 0.0:
		return
	var hit: float = -vn - maxf(-_gravity_dt.dot(nrm), 0.0)
	var e: float = _restitution if hit > _threshold else 0.0
	_vel[i] = v - nrm * ((1.0 + e) * vn)
