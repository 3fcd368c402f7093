@tool
class_name MazeHolePlacer
extends RefCounted
## Puts black holes into a carved maze without ever cutting a start off from the goal: each
## candidate cell is tried in turn and kept only when a flood fill (MazeFlood, holes
## blocking) still finds the goal from every start. Easy mazes take dead ends first (a ball
## only meets those holes when it turns into a dead end); harder ones take corridor cells
## too, so the way to the goal passes holes.


## Adds up to `count` holes to `level` (walls and starts already set) at cell centres of
## `carver`'s grid, `cell` px wide; `difficulty` (0..1) is the chance a pick is a corridor
## cell rather than a dead end. Returns how many were placed.
static func place(
	level: BoardLevel,
	carver: MazeCarver,
	cell: float,
	count: int,
	difficulty: float,
	rng: RandomNumberGenerator
) -> int:
	if count <= 0:
		return 0
	var dead_ends: Array[Vector2i] = []
	var corridors: Array[Vector2i] = []
	var kept_clear := _kept_clear(level, carver, cell, difficulty)
	for r in carver.rows:
		for c in carver.cols:
			var here := Vector2i(c, r)
			if kept_clear.has(here):
				continue
			if carver.closed_sides(here) == 3:
				dead_ends.append(here)
			else:
				corridors.append(here)
	_shuffle(dead_ends, rng)
	_shuffle(corridors, rng)
	var walls_free := MazeFlood.new(level, false).free
	var holes := PackedVector2Array()
	var blocked := {}
	while holes.size() < count and not (dead_ends.is_empty() and corridors.is_empty()):
		var from_corridor := (
			corridors.size() > 0 and (dead_ends.is_empty() or rng.randf() < difficulty)
		)
		var pick: Vector2i = corridors.pop_back() if from_corridor else dead_ends.pop_back()
		holes.append((Vector2(pick) + Vector2(0.5, 0.5)) * cell)
		level.holes = holes
		blocked[pick] = true
		if (
			not _cells_reach_room(level, carver, cell, blocked)
			or not _every_start_reaches_goal(level, walls_free)
		):
			holes.remove_at(holes.size() - 1)
			blocked.erase(pick)
	level.holes = holes
	return holes.size()


## True when every ball start of `level` still reaches the goal with the holes blocking.
static func every_start_reaches_goal(level: BoardLevel) -> bool:
	return _every_start_reaches_goal(level, MazeFlood.new(level, false).free)


static func _every_start_reaches_goal(level: BoardLevel, walls_free: PackedByteArray) -> bool:
	var flood := MazeFlood.new(level, true, walls_free)
	for start in level.ball_starts:
		if not flood.reaches_goal(start):
			return false
	return true


# The stricter, fairer test: with every hole's whole cell closed, each start's cell still
# joins the goal room through open cell sides. (The flood alone would accept a way that
# squeezes past a hole at a junction, which no player should have to do.)
static func _cells_reach_room(
	level: BoardLevel, carver: MazeCarver, cell: float, blocked: Dictionary
) -> bool:
	var seen := {}
	var queue: Array[Vector2i] = []
	for room_cell in carver.room_cells():
		seen[room_cell] = true
		queue.append(room_cell)
	var steps: Array[Vector2i] = [Vector2i.LEFT, Vector2i.RIGHT, Vector2i.UP, Vector2i.DOWN]
	var head := 0
	while head < queue.size():
		var here := queue[head]
		head += 1
		for step in steps:
			var next := here + step
			if seen.has(next) or blocked.has(next) or not carver.is_open(here, next):
				continue
			seen[next] = true
			queue.append(next)
	for start in level.ball_starts:
		if not seen.has(Vector2i((start / cell).floor())):
			return false
	return true


# Cells never given a hole: the goal room, the starts and their neighbours (a ball must get
# going before it meets a hole), and on easier mazes the cells round the goal room.
static func _kept_clear(
	level: BoardLevel, carver: MazeCarver, cell: float, difficulty: float
) -> Dictionary:
	var clear := {}
	var around: Array[Vector2i] = [
		Vector2i.ZERO, Vector2i.LEFT, Vector2i.RIGHT, Vector2i.UP, Vector2i.DOWN
	]
	for room_cell in carver.room_cells():
		clear[room_cell] = true
		if difficulty < 0.5:
			for step in around:
				clear[room_cell + step] = true
	for start in level.ball_starts:
		var start_cell := Vector2i((start / cell).floor())
		for step in around:
			clear[start_cell + step] = true
	return clear


static func _shuffle(cells: Array[Vector2i], rng: RandomNumberGenerator) -> void:
	for i in range(cells.size() - 1, 0, -1):
		var j := rng.randi_range(0, i)
		var swap := cells[i]
		cells[i] = cells[j]
		cells[j] = swap
