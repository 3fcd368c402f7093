class_name MazeGrid
extends RefCounted
## A maze board seen as its grid: which cell a point is in and which cell sides are walls.
## Built from the board's wall segments. A wall on the grid's lines closes the cell sides it
## runs along; a wall off them (a slanted one, or one whose end a designer moved off a grid
## point) closes every side between two neighbouring cells whose centres it separates, the
## grid's nearest picture of it, so one such wall no longer costs the board its planner
## (the pilot learns where the physics differs). Only a board without a grid (`is_grid`
## false) is steered without the planner.
##
## `slide(cell, dir)` is where a ball ends up when the board is tilted hard toward one of
## eight directions and held until it stops: it rolls on while a side is open, and with a
## diagonal tilt it follows whichever of its two axes is open.

## The eight tilt directions, as unit steps in cells.
const DIRECTIONS: Array[Vector2i] = [
	Vector2i(1, 0),
	Vector2i(-1, 0),
	Vector2i(0, 1),
	Vector2i(0, -1),
	Vector2i(1, 1),
	Vector2i(1, -1),
	Vector2i(-1, 1),
	Vector2i(-1, -1),
]
## Moves per cell: the eight hard tilts (slides), then steps made by tilting and braking:
## one cell right, left, down, up (DIRECTIONS 0..3), then two cells each way, and so on up
## to MAX_RUN cells. A step stops short of a hole that a slide would roll into.
const MAX_RUN := 3
const FIRST_STEP := 8
const MOVES := FIRST_STEP + 4 * MAX_RUN
## How far off a grid line a wall end may be and still count as on it, px.
const SNAP := 0.5
## Balls that fit in a line in one corridor cell.
const QUEUE_CAP := 3

var cols := 0
var rows := 0
## Size of one cell (corridor plus one wall), px.
var cell := Vector2.ONE
## True when the board has a grid the planner can use.
var is_grid := true
## Walls that do not lie on the grid's lines (drawn onto it by the cells they separate).
var off_grid_walls := 0
## horizontal[r * cols + c]: a wall on grid line r across cell column c (r in 0..rows).
var horizontal := PackedByteArray()
## vertical[r * (cols + 1) + c]: a wall on grid line c down cell row r (c in 0..cols).
var vertical := PackedByteArray()
## slides[cell_index * MOVES + move] → the cell a move takes a ball to, or -1 when the
## ball would roll over a black hole on the way.
var slides := PackedInt32Array()
## arrivals[cell_index * MOVES + move] → the cell a ball passes last before it stops
## (the cell it started in when it does not move). Balls that stop in one corridor cell
## queue back into it (see `queue_up`).
var arrivals := PackedInt32Array()
## 1 for a cell with a black hole in it (hard mode).
var hole_cells := PackedByteArray()


## Reads the grid of a maze `level`; with `with_holes`, cells holding a black hole swallow
## any ball that rolls through them.
func _init(level: BoardLevel, with_holes := false) -> void:
	cols = level.grid_cols
	rows = level.grid_rows
	if cols <= 0 or rows <= 0 or level.size.x <= 0.0 or level.size.y <= 0.0:
		is_grid = false
		return
	cell = Vector2(level.size.x / float(cols), level.size.y / float(rows))
	horizontal.resize(cols * (rows + 1))
	vertical.resize((cols + 1) * rows)
	for i in range(0, level.walls.size() - 1, 2):
		_mark(level.walls[i], level.walls[i + 1])
	hole_cells.resize(cell_count())
	if with_holes:
		for h in level.holes:
			hole_cells[cell_at(h)] = 1
	_build_slides()


## Number of cells.
func cell_count() -> int:
	return cols * rows


## The index of the cell containing `pos` (clamped to the board).
func cell_at(pos: Vector2) -> int:
	var c := clampi(floori(pos.x / cell.x), 0, cols - 1)
	var r := clampi(floori(pos.y / cell.y), 0, rows - 1)
	return r * cols + c


## The centre of cell `index`, px.
func cell_center(index: int) -> Vector2:
	@warning_ignore("integer_division")  # the row of a cell index: whole rows
	return (Vector2(index % cols, index / cols) + Vector2(0.5, 0.5)) * cell


## True when a ball in cell (c, r) can roll one cell in direction (dx, 0) or (0, dy).
func is_open(c: int, r: int, dx: int, dy: int) -> bool:
	if dx > 0:
		return c + 1 < cols and vertical[r * (cols + 1) + c + 1] == 0
	if dx < 0:
		return c > 0 and vertical[r * (cols + 1) + c] == 0
	if dy > 0:
		return r + 1 < rows and horizontal[(r + 1) * cols + c] == 0
	if dy < 0:
		return r > 0 and horizontal[r * cols + c] == 0
	return false


## Where `move` (a slide 0..7 or a step 8..11) takes a ball from cell `index`.
func slide(index: int, move: int) -> int:
	return slides[index * MOVES + move]


## Balls that end a move in one corridor cell queue up: at most QUEUE_CAP fit in a line
## between its walls (a ball is 10 px across, a corridor cell 25 px long), so the rest wait
## in the cell they arrived from. Moves the extra balls of `ends` (the cells `move` takes
## balls from `starts` to, first `n` entries) back, in place.
func queue_up(starts: PackedInt32Array, ends: PackedInt32Array, n: int, move: int) -> void:
	for b in n:
		var end := ends[b]
		var count := 0
		for o in n:
			if ends[o] == end:
				count += 1
		if count <= QUEUE_CAP or starts[b] == end:
			continue
		var back := arrivals[starts[b] * MOVES + move]
		if back != end and _is_corridor(end, back):
			ends[b] = back


## True for a step (tilt, then brake after some cells), false for a slide.
static func is_step(move: int) -> bool:
	return move >= FIRST_STEP


## The direction of a move, in cells.
static func direction(move: int) -> Vector2i:
	return DIRECTIONS[(move - FIRST_STEP) % 4] if is_step(move) else DIRECTIONS[move]


## The step of `cells` (1..MAX_RUN) cells toward DIRECTIONS[`dir`] (0..3).
static func step_move(dir: int, cells: int) -> int:
	return FIRST_STEP + (cells - 1) * 4 + dir


## Cells a step goes at most (0 for a slide).
static func run_length(move: int) -> int:
	@warning_ignore("integer_division")  # whole runs of four directions
	return (move - FIRST_STEP) / 4 + 1 if is_step(move) else 0


## Straight-line px between the centres of cells `a` and `b` along the grid (how far a ball
## rolls from one to the other in a move).
func travel(a: int, b: int) -> float:
	@warning_ignore("integer_division")  # rows of cell indices: whole rows
	var rows_apart := absi(a / cols - b / cols)
	return absi(a % cols - b % cols) * cell.x + rows_apart * cell.y


func _build_slides() -> void:
	slides.resize(cell_count() * MOVES)
	arrivals.resize(cell_count() * MOVES)
	for index in cell_count():
		for d in FIRST_STEP:
			slides[index * MOVES + d] = _roll(index, DIRECTIONS[d], index * MOVES + d)
		for m in range(FIRST_STEP, MOVES):
			slides[index * MOVES + m] = _step(index, m, index * MOVES + m)


# True when `index` is walled on both sides across the way in from `back` (a neighbour).
func _is_corridor(index: int, back: int) -> bool:
	var c := index % cols
	@warning_ignore("integer_division")  # the row of a cell index: whole rows
	var r := index / cols
	if absi(index - back) == 1:  # came in along x
		return not is_open(c, r, 0, 1) and not is_open(c, r, 0, -1)
	return not is_open(c, r, 1, 0) and not is_open(c, r, -1, 0)


# Steps from `index` by `move` and stores the last cell passed in arrivals[`slot`].
func _step(index: int, move: int, slot: int) -> int:
	var step := direction(move)
	var c := index % cols
	@warning_ignore("integer_division")  # the row of a cell index: whole rows
	var r := index / cols
	arrivals[slot] = index
	for _s in run_length(move):
		if not is_open(c, r, step.x, step.y):
			break
		arrivals[slot] = r * cols + c
		c += step.x
		r += step.y
		if hole_cells[r * cols + c] != 0:
			return -1
	return r * cols + c


# Rolls from `index` toward `step` and stores the last cell passed in arrivals[`slot`].
# A diagonal tilt pulls along both axes at once, so where both open the ball may go either
# way first: the model takes x first, but if y first meets a hole the move counts as deadly.
func _roll(index: int, step: Vector2i, slot: int) -> int:
	var end := _roll_path(index, step, false, slot)
	if end >= 0 and step.x != 0 and step.y != 0 and _roll_path(index, step, true, -1) < 0:
		return -1
	return end


# One way of rolling: at each cell the x axis first (or y when `y_first`); -1 on a hole.
# Stores the last cell passed in arrivals[`slot`] unless `slot` is -1.
func _roll_path(index: int, step: Vector2i, y_first: bool, slot: int) -> int:
	var c := index % cols
	@warning_ignore("integer_division")  # the row of a cell index: whole rows
	var r := index / cols
	var last := index
	var axes := (
		[Vector2i(0, step.y), Vector2i(step.x, 0)]
		if y_first
		else [Vector2i(step.x, 0), Vector2i(0, step.y)]
	)
	for _guard in cols + rows + 2:
		var moved := false
		for axis: Vector2i in axes:
			if axis == Vector2i.ZERO or not is_open(c, r, axis.x, axis.y):
				continue
			last = r * cols + c
			c += axis.x
			r += axis.y
			moved = true
			if hole_cells[r * cols + c] != 0:
				return -1
		if not moved:
			break
	if slot >= 0:
		arrivals[slot] = last
	return r * cols + c


func _mark(a: Vector2, b: Vector2) -> void:
	var ga := a / cell
	var gb := b / cell
	var on_x := (
		absf(ga.x - roundf(ga.x)) * cell.x < SNAP and absf(gb.x - roundf(gb.x)) * cell.x < SNAP
	)
	var on_y := (
		absf(ga.y - roundf(ga.y)) * cell.y < SNAP and absf(gb.y - roundf(gb.y)) * cell.y < SNAP
	)
	if not (on_x and on_y) or (a.x != b.x and a.y != b.y):
		off_grid_walls += 1
		_mark_separated(a, b)
		return
	var c0 := roundi(minf(ga.x, gb.x))
	var c1 := roundi(maxf(ga.x, gb.x))
	var r0 := roundi(minf(ga.y, gb.y))
	var r1 := roundi(maxf(ga.y, gb.y))
	if r0 == r1 and r0 >= 0 and r0 <= rows:
		for c in range(maxi(c0, 0), mini(c1, cols)):
			horizontal[r0 * cols + c] = 1
	elif c0 == c1 and c0 >= 0 and c0 <= cols:
		for r in range(maxi(r0, 0), mini(r1, rows)):
			vertical[r * (cols + 1) + c0] = 1


# Closes the side between each pair of neighbouring cells whose centres the wall from `a`
# to `b` lies between (the segment joining the centres crosses the wall).
func _mark_separated(a: Vector2, b: Vector2) -> void:
	var low := Vector2(minf(a.x, b.x), minf(a.y, b.y)) / cell
	var high := Vector2(maxf(a.x, b.x), maxf(a.y, b.y)) / cell
	for r in range(maxi(floori(low.y) - 1, 0), mini(ceili(high.y) + 1, rows)):
		for c in range(maxi(floori(low.x) - 1, 0), mini(ceili(high.x) + 1, cols)):
			var centre := (Vector2(c, r) + Vector2(0.5, 0.5)) * cell
			if c + 1 < cols and _separates(a, b, centre, centre + Vector2(cell.x, 0.0)):
				vertical[r * (cols + 1) + c + 1] = 1
			if r + 1 < rows and _separates(a, b, centre, centre + Vector2(0.0, cell.y)):
				horizontal[(r + 1) * cols + c] = 1


# True when the segment a-b crosses the segment p-q (a point exactly on the wall's line
# counts as on its left, so a wall through a centre closes one side of it, not two).
static func _separates(a: Vector2, b: Vector2, p: Vector2, q: Vector2) -> bool:
	var wall := b - a
	var p_left := wall.cross(p - a) >= 0.0
	var q_left := wall.cross(q - a) >= 0.0
	if p_left == q_left:
		return false
	var link := q - p
	var a_side := link.cross(a - p)
	var b_side := link.cross(b - p)
	return (a_side >= 0.0) != (b_side >= 0.0) or a_side == 0.0 or b_side == 0.0
