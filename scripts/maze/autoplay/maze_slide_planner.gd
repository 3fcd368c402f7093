extends RefCounted
## Plans tilts for all balls at once on a grid maze. A state is the set of cells the balls
## are in; a move is a hard tilt toward one of eight directions held until every ball stops,
## or (in hard mode) a one-cell step (MazeGrid.slide); moves that would roll a ball over a
## black hole are never taken. Breadth-first search finds the shortest list of moves that
## gathers every ball into one cell close to the goal; from there the pack rolls in as one.
## (One tilt moves every ball, so gathering first is what makes the goal reachable.)

const MazeGrid := preload("res://scripts/maze/autoplay/maze_grid.gd")
const MazeNav := preload("res://scripts/maze/autoplay/maze_nav.gd")

## Cost of one more move, in pixels of distance left to the goal.
const MOVE_COST := 8.0
## Once the balls can be gathered, plans at most this many moves longer are still tried.
const EXTRA_MOVES := 4
## Search no further than this many states.
const MAX_STATES := 250000

var grid: MazeGrid
var nav: MazeNav
## The state the last plan ends in (cells, sorted), and its moves.
var target := PackedInt32Array()
var moves := PackedInt32Array()

var _bits := 1
var _cell_distance := PackedFloat32Array()


func _init(p_grid: MazeGrid, p_nav: MazeNav) -> void:
	grid = p_grid
	nav = p_nav
	while (1 << _bits) < grid.cell_count():
		_bits += 1
	_cell_distance.resize(grid.cell_count())
	for i in grid.cell_count():
		_cell_distance[i] = minf(nav.distance_at(grid.cell_center(i)), 1.0e6)


## Plans from balls in `cells`; `order` is the order directions are tried (ties go to the
## first, so a shuffled order gives another equally short plan). Returns false when no
## state gathers the balls (then `target` is the state nearest the goal found).
func plan(cells: PackedInt32Array, order: PackedInt32Array) -> bool:
	var n := cells.size()
	if n == 0 or n * _bits > 62:
		return false
	var keys := PackedInt64Array([_encode(cells)])
	var parents := PackedInt32Array([-1])
	var dirs := PackedByteArray([0])
	var depth := PackedInt32Array([0])
	var seen := {keys[0]: 0}
	var best := 0
	var best_score := INF
	var gathered := false
	var depth_limit := 1 << 30
	var head := 0
	var state := PackedInt32Array()
	state.resize(n)
	var next := PackedInt32Array()
	next.resize(n)
	var slides := grid.slides
	var stride := MazeGrid.MOVES
	while head < keys.size():
		_decode(keys[head], state)
		var score := _score(state, depth[head])
		if score < best_score:
			best_score = score
			best = head
		if _all_same(state) and not gathered:
			gathered = true
			# A gathering this many moves deeper would have to be much nearer the goal.
			depth_limit = depth[head] + EXTRA_MOVES
		if keys.size() < MAX_STATES and depth[head] < depth_limit:
			for d in order:
				var deadly := false
				for b in n:
					next[b] = slides[state[b] * stride + d]
					deadly = deadly or next[b] < 0
				if deadly:
					continue  # a ball would roll over a black hole
				var key := _sorted_key(next, n)
				if not seen.has(key):
					seen[key] = keys.size()
					keys.append(key)
					parents.append(head)
					dirs.append(d)
					depth.append(depth[head] + 1)
		head += 1
	target = PackedInt32Array()
	target.resize(n)
	_decode(keys[best], target)
	moves = PackedInt32Array()
	var at := best
	while parents[at] >= 0:
		moves.append(dirs[at])
		at = parents[at]
	moves.reverse()
	return gathered


## The balls' cells after `moves[0..count)` from `cells` (sorted).
func predict(cells: PackedInt32Array, dir: int) -> PackedInt32Array:
	var next := PackedInt32Array()
	for c in cells:
		next.append(grid.slide(c, dir))
	next.sort()
	return next


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


# A gathered state scores its cell's distance to the goal; a scattered one scores far worse
# (the sum of every ball's distance), so a gathering always wins when one exists.
func _score(state: PackedInt32Array, moves_so_far: int) -> float:
	var cost := MOVE_COST * float(moves_so_far)
	if _all_same(state):
		return cost + _cell_distance[state[0]]
	var total := 1.0e5
	for c in state:
		total += _cell_distance[c]
	return cost + total


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
