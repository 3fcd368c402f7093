class_name MazeSlidePlanner
extends RefCounted
## Plans tilts for all balls at once on a grid maze. A state is the set of cells the balls
## are in; a move is a hard tilt toward one of eight directions held until every ball stops,
## or (in hard mode) a one-cell step (MazeGrid.slide); moves that would roll a ball over a
## black hole are never taken. Breadth-first search finds the shortest list of moves that
## gathers every ball into one cell close to the goal; from there the pack rolls in as one.
## (One tilt moves every ball, so gathering first is what makes the goal reachable.)

## A plan's cost is the time it takes, in px a ball rolls at full speed: each move costs
## its longest roll plus MOVE_COST for starting and stopping.
const MOVE_COST := 30.0
## How much the search trusts its estimate of the cost left (> 1: it finds a plan sooner,
## not always the quickest).
const HEURISTIC_WEIGHT := 2.5
## Share of a plan's cost that counts when it cannot gather the balls.
const SCATTERED_COST_SHARE := 0.2
## Search no further than this many states, and grow at most MAX_EXPANDED of them.
const MAX_STATES := 250000
const MAX_EXPANDED := 25000

var grid: MazeGrid
var nav: MazeNav
## The state the last plan ends in (cells, sorted), and its moves.
var target := PackedInt32Array()
var moves := PackedInt32Array()

var _bits := 1
## What moves really did from some states: _learned[state key][move] → the state key after.
var _learned := {}
var _cell_distance := PackedFloat32Array()
## A cell this near the goal (path length, px) holds a pack that is already in it.
var _goal_reach := 0.0


func _init(p_grid: MazeGrid, p_nav: MazeNav) -> void:
	grid = p_grid
	nav = p_nav
	while (1 << _bits) < grid.cell_count():
		_bits += 1
	_cell_distance.resize(grid.cell_count())
	for i in grid.cell_count():
		_cell_distance[i] = minf(nav.distance_at(grid.cell_center(i)), 1.0e6)
	_goal_reach = grid.cell.length() * 0.75


## Plans from balls in `cells`; `order` is the order moves are tried (ties go to the first,
## so a shuffled order gives another plan). Best-first: the states whose balls are nearest
## the goal are grown first, so big mazes with many balls are searched where it matters.
## Returns true when the plan gathers every ball in one cell; otherwise `moves` lead to the
## state nearest the goal found (`target`), a start to plan again from.
func plan(cells: PackedInt32Array, order: PackedInt32Array) -> bool:
	var n := cells.size()
	if n == 0 or n * _bits > 62:
		return false
	var keys := PackedInt64Array([_encode(cells)])
	var parents := PackedInt32Array([-1])
	var dirs := PackedByteArray([0])
	var spent := PackedFloat32Array([0.0])
	var seen := {keys[0]: 0}
	var open := MinHeap.new()
	open.push(0.0, 0)
	var best := 0
	var best_score := INF
	var state := PackedInt32Array()
	state.resize(n)
	var next := PackedInt32Array()
	next.resize(n)
	var slides := grid.slides
	var stride := MazeGrid.MOVES
	var expanded := 0
	while not open.is_empty() and expanded < MAX_EXPANDED:
		var head := open.pop()
		expanded += 1
		_decode(keys[head], state)
		var score := _score(state, spent[head])
		if score < best_score:
			best_score = score
			best = head
		if _all_same(state) and _cell_distance[state[0]] <= _goal_reach:
			break  # gathered in the goal: nothing better to find
		if keys.size() >= MAX_STATES:
			continue
		var learned: Dictionary = _learned.get(keys[head], {})
		for d in order:
			var deadly := false
			if learned.has(d):
				var after: int = learned[d]
				_decode(after, next)
			else:
				for b in n:
					next[b] = slides[state[b] * stride + d]
					deadly = deadly or next[b] < 0
			if deadly:
				continue  # a ball would roll over a black hole
			if not learned.has(d):
				grid.queue_up(state, next, n, d)
			var longest := 0.0
			for b in n:
				longest = maxf(longest, grid.travel(state[b], next[b]))
			var key := _sorted_key(next, n)
			if seen.has(key):
				continue
			seen[key] = keys.size()
			var cost := spent[head] + MOVE_COST + longest
			open.push(cost + HEURISTIC_WEIGHT * _estimate(next), keys.size())
			keys.append(key)
			parents.append(head)
			dirs.append(d)
			spent.append(cost)
	target = PackedInt32Array()
	target.resize(n)
	_decode(keys[best], target)
	moves = PackedInt32Array()
	var at := best
	while parents[at] >= 0:
		moves.append(dirs[at])
		at = parents[at]
	moves.reverse()
	return _all_same(target)


## The balls' cells after `moves[0..count)` from `cells` (sorted).
func predict(cells: PackedInt32Array, dir: int) -> PackedInt32Array:
	var known: Dictionary = _learned.get(_encode(cells), {}) if not cells.is_empty() else {}
	if known.has(dir):
		var after := cells.duplicate()
		var key: int = known[dir]
		_decode(key, after)
		return after
	var next := PackedInt32Array()
	for c in cells:
		next.append(grid.slide(c, dir))
	grid.queue_up(cells, next, cells.size(), dir)
	next.sort()
	return next


## Remembers that `move` took balls in `before` (cells, sorted) to `after` (sorted): plans
## from that state expect it from now on.
func remember(before: PackedInt32Array, move: int, after: PackedInt32Array) -> void:
	if before.size() != after.size() or before.is_empty() or before.size() * _bits > 62:
		return
	var key := _encode(before)
	var known: Dictionary = _learned.get(key, {})
	known[move] = _encode(after)
	_learned[key] = known


## Never gather in `cell` again (the pack did not make it from there to the goal).
func ban(cell: int) -> void:
	if cell >= 0 and cell < _cell_distance.size():
		_cell_distance[cell] = 1.0e4


## True when `cell` was banned.
func is_banned(cell: int) -> bool:
	return cell >= 0 and cell < _cell_distance.size() and _cell_distance[cell] >= 1.0e4


## Cells of balls at `positions`, sorted (the planner's state).
func cells_of(positions: PackedVector2Array) -> PackedInt32Array:
	var cells := PackedInt32Array()
	for p in positions:
		cells.append(grid.cell_at(p))
	cells.sort()
	return cells


# A gathered state scores its cell's distance to the goal plus what the moves there cost
# (`spent`); a scattered one scores far worse (the sum of every ball's distance, the cost
# counting less: a plan that only brings the balls nearer should bring them as near as it
# can), so a gathering always wins when one exists.
func _score(state: PackedInt32Array, spent: float) -> float:
	if _all_same(state):
		return spent + _cell_distance[state[0]]
	var total := 1.0e5
	for c in state:
		total += _cell_distance[c]
	return total + spent * SCATTERED_COST_SHARE


# The cost left from `state`, estimated: the farthest ball's path length to the goal, with
# the mean of all of them so a state with more balls nearer sorts first.
func _estimate(state: PackedInt32Array) -> float:
	var far := 0.0
	var total := 0.0
	for c in state:
		far = maxf(far, _cell_distance[c])
		total += _cell_distance[c]
	return 0.5 * (far + total / float(state.size()))


static func _all_same(state: PackedInt32Array) -> bool:
	for c in state:
		if c != state[0]:
			return false
	return true


# Insertion-sorts the first `n` cells in place and packs them into one key.
func _sorted_key(cells: PackedInt32Array, n: int) -> int:
	for i in range(1, n):
		var v: int = cells[i]
		var j := i - 1
		while j >= 0 and cells[j] > v:
			cells[j + 1] = cells[j]
			j -= 1
		cells[j + 1] = v
	var key := 0
	for i in n:
		key = (key << _bits) | cells[i]
	return key


func _encode(cells: PackedInt32Array) -> int:
	var sorted := cells.duplicate()
	sorted.sort()
	var key := 0
	for c in sorted:
		key = (key << _bits) | c
	return key


func _decode(key: int, out: PackedInt32Array) -> void:
	var mask := (1 << _bits) - 1
	for i in range(out.size() - 1, -1, -1):
		out[i] = key & mask
		key >>= _bits
