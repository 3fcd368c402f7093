@tool
class_name MazeCarver
extends RefCounted
## The wall grid of a generated maze: every cell starts closed, a random depth-first walk
## from the goal room opens a perfect maze (one way between any two cells), and then a
## share of the remaining inner walls is knocked out so there are loops. Walls are flags on
## the grid lines; `wall_segments()` joins runs of them into as few walls as possible.

var cols: int
var rows: int
## Wall flags: horizontal[r * cols + c] is the wall on grid line y = r above cell (c, r);
## vertical[c * rows + r] the wall on grid line x = c left of cell (c, r).
var horizontal := PackedByteArray()
var vertical := PackedByteArray()
## The top-left cell of the open 2 × 2 goal room.
var room := Vector2i.ZERO


func _init(columns: int, row_count: int) -> void:
	cols = columns
	rows = row_count
	horizontal.resize((rows + 1) * cols)
	horizontal.fill(1)
	vertical.resize((cols + 1) * rows)
	vertical.fill(1)
	@warning_ignore("integer_division")  # the room sits on the middle cells
	room = Vector2i(cols / 2 - 1, rows / 2 - 1)
	_open_between(room, room + Vector2i.RIGHT)
	_open_between(room + Vector2i.DOWN, room + Vector2i.ONE)
	_open_between(room, room + Vector2i.DOWN)
	_open_between(room + Vector2i.RIGHT, room + Vector2i.ONE)


## Carves the perfect maze with `rng`, then opens each inner wall with chance `openness`.
func carve(rng: RandomNumberGenerator, openness: float) -> void:
	var seen := PackedByteArray()
	seen.resize(cols * rows)
	for cell in room_cells():
		seen[_index(cell)] = 1
	var stack: Array[Vector2i] = [room]
	var steps: Array[Vector2i] = [Vector2i.LEFT, Vector2i.RIGHT, Vector2i.UP, Vector2i.DOWN]
	while not stack.is_empty():
		var here: Vector2i = stack.back()
		var options: Array[Vector2i] = []
		for step in steps:
			var neighbour := here + step
			if contains(neighbour) and seen[_index(neighbour)] == 0:
				options.append(neighbour)
		if options.is_empty():
			stack.pop_back()
			continue
		var next: Vector2i = options[rng.randi_range(0, options.size() - 1)]
		_open_between(here, next)
		seen[_index(next)] = 1
		stack.append(next)
	for r in range(1, rows):
		for c in cols:
			if rng.randf() < openness:
				horizontal[r * cols + c] = 0
	for c in range(1, cols):
		for r in rows:
			if rng.randf() < openness:
				vertical[c * rows + r] = 0


## The four cells of the goal room.
func room_cells() -> Array[Vector2i]:
	return [room, room + Vector2i.RIGHT, room + Vector2i.DOWN, room + Vector2i.ONE]


func contains(cell: Vector2i) -> bool:
	return cell.x >= 0 and cell.y >= 0 and cell.x < cols and cell.y < rows


## How many of the cell's four sides are walls.
func closed_sides(cell: Vector2i) -> int:
	var top := horizontal[cell.y * cols + cell.x]
	var bottom := horizontal[(cell.y + 1) * cols + cell.x]
	var left := vertical[cell.x * rows + cell.y]
	var right := vertical[(cell.x + 1) * rows + cell.y]
	return top + bottom + left + right


## True when `a` and `b` are neighbouring cells of the grid with no wall between them.
func is_open(a: Vector2i, b: Vector2i) -> bool:
	if not contains(a) or not contains(b) or absi(a.x - b.x) + absi(a.y - b.y) != 1:
		return false
	if a.x != b.x:
		return vertical[maxi(a.x, b.x) * rows + a.y] == 0
	return horizontal[maxi(a.y, b.y) * cols + a.x] == 0


## Wall segments in cell units ([a, b] pairs of Vector2), runs along each grid line joined.
func wall_segments() -> Array[PackedVector2Array]:
	var walls: Array[PackedVector2Array] = []
	for r in rows + 1:
		var start := -1
		for c in cols + 1:
			var on := c < cols and horizontal[r * cols + c] == 1
			if on and start < 0:
				start = c
			elif not on and start >= 0:
				walls.append(PackedVector2Array([Vector2(start, r), Vector2(c, r)]))
				start = -1
	for c in cols + 1:
		var start := -1
		for r in rows + 1:
			var on := r < rows and vertical[c * rows + r] == 1
			if on and start < 0:
				start = r
			elif not on and start >= 0:
				walls.append(PackedVector2Array([Vector2(c, start), Vector2(c, r)]))
				start = -1
	return walls


func _open_between(a: Vector2i, b: Vector2i) -> void:
	if a.x != b.x:
		vertical[maxi(a.x, b.x) * rows + a.y] = 0
	else:
		horizontal[maxi(a.y, b.y) * cols + a.x] = 0


func _index(cell: Vector2i) -> int:
	return cell.y * cols + cell.x
