class_name BallPairs
extends RefCounted
## Ball–ball contacts between equal masses: the broad phase finds the touching pairs, and
## BallSolve answers them. Internal to scripts/physics; BallWorld owns one.
##
## Broad phase: each ball gets a key (cell << SORT_SHIFT | ball) and one native sort puts
## the balls in cell order. Cells are at least a ball diameter, so a ball only meets balls
## of its own cell, the next cell and the three cells below: two runs of the sorted keys.
## The run below is found by a pointer that only moves forward, as cells only grow along
## the keys. Wrapped rows add candidates but never miss any.
##
## Stripes: the grid's rows are cut into stripes of STRIPE_ROWS rows, and each stripe lists
## the pairs whose first ball (in key order) lies in it, in key order. A pair reaches at
## most STRIPE_ROWS rows past its stripe's first row (the row below, or two below where a
## row wraps), so two stripes of the same parity never share a ball: the solve answers
## every even stripe side by side, then every odd one, each stripe's list in order on one
## thread. That order depends only on where the balls are, so any number of threads gives
## the same result. The lanes are runs of whole stripes, the later ones with fewer balls.

## Sort keys of the broad phase: cell << SORT_SHIFT | ball index.
const SORT_SHIFT := 21
const SORT_MASK := (1 << 21) - 1
## Larger than any sort key: it ends each scan without a bounds test.
const SORT_SENTINEL := 0x7fffffffffffffff
## Rows of cells per stripe: at least 2, or stripes of one parity could share a ball.
const STRIPE_ROWS := 2
## Fewer pairs than this (of one parity) are answered on the world's thread: handing them
## to the threads would cost more than it saves (the same result either way).
const PAIRS_WORTH_THREADS := 64
## Entries a stripe's pair list starts with when it first needs room (it doubles after).
const PAIRS_ROOM := 32

## Each stripe's touching pairs, as (i, j) slot pairs in key order: the first
## stripe_used[s] entries of stripe_pairs[s] (the arrays keep their size from step to step:
## freeing and growing them again every step cost allocations, and on threads an allocation
## freed by another thread waits for that thread's heap).
var stripe_pairs: Array[PackedInt32Array] = []
var stripe_used := PackedInt32Array()

var _solve := BallSolve.new()
var _keys := PackedInt64Array()
var _pos := PackedVector2Array()
var _rad := PackedFloat32Array()
var _key_cell := PackedInt32Array()
var _origin := Vector2.ZERO
var _inv_cell := 1.0
var _cols := 1
var _last_cell := Vector2i.ZERO
## Sorted-key index of each stripe's first ball (one more entry: the ball count).
var _stripe_first := PackedInt32Array()
## Lane k runs stripes _lane_bounds[k] .. _lane_bounds[k + 1].
var _lane_bounds := PackedInt32Array()
## True while find() also answers the even stripes it has listed.
var _solve_even := false
## Pairs find() listed in each lane's stripes, by parity: lane k's at [2k] (even), [2k + 1].
var _lane_pair_counts := PackedInt32Array()
## The parity of stripes solve_stripes() answers.
var _parity := 0


## Starts the step's solve (see BallSolve.begin()); runs every step, contacts on or off.
func begin(
	b: BallStore, restitution: float, threshold: float, wake_speed: float, gravity_dt: Vector2
) -> void:
	_solve.begin(b, restitution, threshold, wake_speed, gravity_dt)
	stripe_used.fill(0)


## Broad phase: lists every touching pair of balls in stripe_pairs. With `solve_even`, each
## lane also answers its even stripes as soon as it has listed them (one hand-off to the
## threads fewer; the same result, as listing reads only positions and radii).
func find(b: BallStore, g: StaticGeometry, lanes: BallLanes, solve_even: bool) -> void:
	var n: int = b.ids.size()
	if n < 2:
		b.keys_valid = false  # no sort, no key slots: a lone ball is binned again
		_lane_bounds = PackedInt32Array([0, 0])
		_lane_pair_counts = PackedInt32Array([0, 0])
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
		_key_cell = b.key_cell
		lanes.run(_bin_range, n)
		b.keys_valid = true
	_keys = b.cell_keys.duplicate()
	_keys.append(SORT_SENTINEL)
	_keys.sort()
	# Next step's keys start in this order (the motion stage finds a ball's in sorted_keys).
	b.cell_keys = _keys.slice(0, n)
	b.sorted_keys = _keys
	_cut_stripes(g.rows, n, lanes.lanes_for(n))
	_solve_even = solve_even
	_lane_pair_counts.resize(2 * (_lane_bounds.size() - 1))
	_lane_pair_counts.fill(0)
	lanes.run_spans(_find_stripes, _lane_bounds)


## Answers the pairs of every stripe of `parity` (0 even, 1 odd), side by side; a few
## pairs on the world's thread.
func solve_stripes(lanes: BallLanes, parity: int) -> void:
	_parity = parity
	var count := 0
	for k: int in range(parity, _lane_pair_counts.size(), 2):
		count += _lane_pair_counts[k]
	if count == 0:
		return
	if count < PAIRS_WORTH_THREADS:
		_solve_stripes(0, 0, 0, _lane_bounds[_lane_bounds.size() - 1])
	else:
		lanes.run_spans(_solve_stripes, _lane_bounds)


## Hands the step's supports to the store; runs every step, after the solve.
func finish(b: BallStore) -> void:
	_solve.finish(b)


## Stripe starts in the sorted keys, and lanes of whole stripes, each with fewer balls than
## the one before (see BallLanes.tapered_bounds()).
func _cut_stripes(rows: int, n: int, lanes: int) -> void:
	var stripes: int = ceili(float(rows) / STRIPE_ROWS)
	while stripe_pairs.size() < stripes:
		stripe_pairs.append(PackedInt32Array())
		stripe_used.append(0)
	_stripe_first.resize(stripes + 1)
	for s: int in stripes:
		_stripe_first[s] = _keys.bsearch((s * STRIPE_ROWS * _cols) << SORT_SHIFT)
	_stripe_first[stripes] = n
	lanes = mini(lanes, stripes)
	var balls_before: PackedInt32Array = BallLanes.tapered_bounds(n, lanes)
	_lane_bounds.resize(lanes + 1)
	_lane_bounds[0] = 0
	for k: int in range(1, lanes):
		_lane_bounds[k] = _stripe_first.bsearch(balls_before[k])
	_lane_bounds[lanes] = stripes


func _find_stripes(_worker: int, lane: int, from: int, to: int) -> void:
	for s: int in range(from, to):
		var first: int = _stripe_first[s]
		var past: int = _stripe_first[s + 1]
		if past - first < 1:
			continue
		var pairs: PackedInt32Array = stripe_pairs[s]
		var used: int = _find_in_range(pairs, first, past)
		if used == 0:
			continue
		stripe_used[s] = used
		var odd: int = s & 1
		_lane_pair_counts[2 * lane + odd] += used >> 1
		if _solve_even and odd == 0:
			_solve.solve_pairs(pairs, used)


func _solve_stripes(_worker: int, _lane: int, from: int, to: int) -> void:
	for s: int in range(from, to):
		if (s & 1) == _parity and stripe_used[s] > 0:
			_solve.solve_pairs(stripe_pairs[s], stripe_used[s])


func _bin_range(_lane: int, from: int, to: int) -> void:
	var keys: PackedInt64Array = _keys
	var key_cell: PackedInt32Array = _key_cell
	var pos: PackedVector2Array = _pos
	for i: int in range(from, to):
		var ci: Vector2i = Vector2i((pos[i] - _origin) * _inv_cell).clamp(Vector2i.ZERO, _last_cell)
		var cell: int = ci.y * _cols + ci.x
		keys[i] = (cell << SORT_SHIFT) | i
		key_cell[i] = cell


## Lists in `out` every touching pair whose first ball holds sorted key from..to - 1, from
## its start on, growing it when full; returns the entries used (two per pair).
func _find_in_range(out: PackedInt32Array, from: int, to: int) -> int:
	var used := 0
	var room: int = out.size()
	var keys: PackedInt64Array = _keys
	var pos: PackedVector2Array = _pos
	var rad: PackedFloat32Array = _rad
	var mask: int = SORT_MASK
	var cell_bits: int = ~SORT_MASK
	# Key offsets from a cell's first key: two cells on, and the three cells below.
	var next_off: int = 2 << SORT_SHIFT
	var below_off: int = (_cols - 1) << SORT_SHIFT
	var past_below_off: int = (_cols + 2) << SORT_SHIFT
	var below: int = keys.bsearch((keys[from] & cell_bits) + below_off)
	# Each ball has two runs of candidates: its own cell and the next (the keys after its
	# own), then the three cells below (from `below`, a pointer that only moves forward).
	# Each run ends at the first key past it. A lone ball, as most of a flowing board are,
	# is known by two key reads and costs nothing more.
	for k: int in range(from, to):
		var key: int = keys[k]
		var cell_key: int = key & cell_bits
		var end: int = cell_key + next_off
		var first_below: int = cell_key + below_off
		while keys[below] < first_below:
			below += 1
		var past_below: int = cell_key + past_below_off
		if keys[k + 1] >= end and keys[below] >= past_below:
			continue
		var i: int = key & mask
		var pi: Vector2 = pos[i]
		var ri: float = rad[i]
		for run: int in 2:
			var m: int = k + 1 if run == 0 else below
			var past: int = end if run == 0 else past_below
			while keys[m] < past:
				var j: int = keys[m] & mask
				var rr: float = ri + rad[j]
				if pi.distance_squared_to(pos[j]) < rr * rr:
					if used == room:
						room = maxi(2 * room, PAIRS_ROOM)
						out.resize(room)
					out[used] = i
					out[used + 1] = j
					used += 2
				m += 1
	return used
