class_name MazeNav
extends RefCounted
## A distance field over a maze board: for every point of a fine lattice, the length of the
## shortest path a ball's centre can roll from there to the goal, keeping clear of walls
## (and of black holes in hard mode). Paths prefer the middle of corridors, where a ball
## does not scrape caps. The autoplay steers each ball down this field.

## Lattice spacing in pixels.
const SPACING := 2.5
## Extra clearance (px) beyond touching that the paths try to keep.
const COMFORT := 6.0
## How much a path pays for hugging a wall (multiplies its length at zero clearance).
const HUG_COST := 3.0
## Room a path keeps between a ball's centre and a hole's rim, in ball radii.
const HOLE_ROOM := 2.0
## Distance of unreachable points.
const FAR := 1.0e9

var cols := 0
var rows := 0
## Clearance of each lattice point: distance from the ball's edge to the nearest obstacle.
var clearance := PackedFloat32Array()
## Path length to the goal from each lattice point (FAR when unreachable).
var distance := PackedFloat32Array()
var _goal := Vector2.ZERO


## Builds the field for `level`; `with_holes` treats black holes as obstacles.
func _init(level: BoardLevel, with_holes := false) -> void:
	if level == null or level.size.x <= 0.0 or level.size.y <= 0.0:
		push_error("MazeNav: the board has no size")
		return
	cols = ceili(level.size.x / SPACING) + 1
	rows = ceili(level.size.y / SPACING) + 1
	_goal = level.goal_center
	_build_clearance(level, with_holes)
	_build_distance()


## Path length from `pos` to the goal (the nearest lattice point's value).
func distance_at(pos: Vector2) -> float:
	var i := _nearest_free(pos)
	return distance[i] if i >= 0 else FAR


## A point about `ahead` pixels further along the best path from `pos` toward the goal.
## Returns the goal when `pos` is already close to it.
func carrot(pos: Vector2, ahead: float) -> Vector2:
	var i := _nearest_free(pos)
	if i < 0:
		return _goal
	var steps := ceili(ahead / SPACING)
	for _s in steps:
		var next := _downhill(i)
		if next == i:
			break
		i = next
	return _point(i)


## Lattice index → position.
func _point(i: int) -> Vector2:
	@warning_ignore("integer_division")  # the row of a lattice index: whole rows
	return Vector2(float(i % cols), float(i / cols)) * SPACING


func _index(c: int, r: int) -> int:
	return r * cols + c


func _build_clearance(level: BoardLevel, with_holes: bool) -> void:
	var n := cols * rows
	clearance.resize(n)
	clearance.fill(COMFORT * 2.0)
	var reach := level.wall_width * 0.5 + level.ball_radius
	var walls := level.walls
	for w in range(0, walls.size() - 1, 2):
		_stamp_segment(walls[w], walls[w + 1], reach)
	if with_holes:
		# A ball falls once its centre is over the hole: paths keep a ball's width clear of
		# the rim (HOLE_ROOM), and like to keep COMFORT more.
		for h in level.holes:
			_stamp_segment(h, h, level.hole_radius + level.ball_radius * HOLE_ROOM)
	# The board's own edge is a wall too.
	for r in rows:
		for c in cols:
			var p := Vector2(c, r) * SPACING
			var edge := minf(minf(p.x, level.size.x - p.x), minf(p.y, level.size.y - p.y))
			var i := _index(c, r)
			clearance[i] = minf(clearance[i], edge - level.ball_radius)


# Lowers the clearance of every lattice point near the segment a–b (grown by `reach`).
func _stamp_segment(a: Vector2, b: Vector2, reach: float) -> void:
	var margin := reach + COMFORT * 2.0
	var lo := (a.min(b) - Vector2(margin, margin)) / SPACING
	var hi := (a.max(b) + Vector2(margin, margin)) / SPACING
	for r in range(maxi(0, floori(lo.y)), mini(rows, ceili(hi.y) + 1)):
		for c in range(maxi(0, floori(lo.x)), mini(cols, ceili(hi.x) + 1)):
			var p := Vector2(c, r) * SPACING
			var q := Geometry2D.get_closest_point_to_segment(p, a, b)
			var i := _index(c, r)
			clearance[i] = minf(clearance[i], p.distance_to(q) - reach)


func _build_distance() -> void:
	var n := cols * rows
	distance.resize(n)
	distance.fill(FAR)
	var start := _nearest_free(_goal)
	if start < 0:
		push_error("MazeNav: the goal is inside a wall")
		return
	var dist := distance
	var clear := clearance
	dist[start] = 0.0
	var frontier := MinHeap.new()
	frontier.push(0.0, start)
	var dcs := PackedInt32Array([1, -1, 0, 0, 1, 1, -1, -1])
	var drs := PackedInt32Array([0, 0, 1, -1, 1, -1, 1, -1])
	while not frontier.is_empty():
		var i := frontier.pop()
		var cost := frontier.last_cost
		if cost > dist[i]:
			continue
		var c := i % cols
		@warning_ignore("integer_division")  # the row of a lattice index: whole rows
		var r := i / cols
		for o in 8:
			var nc: int = c + dcs[o]
			var nr: int = r + drs[o]
			if nc < 0 or nr < 0 or nc >= cols or nr >= rows:
				continue
			var j := nr * cols + nc
			var cl: float = clear[j]
			if cl < 0.0:
				continue
			var length := SPACING * (1.4142 if o >= 4 else 1.0)
			var hug := maxf(0.0, COMFORT - cl) / COMFORT
			var next_cost := cost + length * (1.0 + HUG_COST * hug)
			if next_cost < dist[j]:
				dist[j] = next_cost
				frontier.push(next_cost, j)
	distance = dist


func _nearest_free(pos: Vector2) -> int:
	var c0 := clampi(roundi(pos.x / SPACING), 0, cols - 1)
	var r0 := clampi(roundi(pos.y / SPACING), 0, rows - 1)
	var best := -1
	var best_d := INF
	for r in range(maxi(0, r0 - 3), mini(rows, r0 + 4)):
		for c in range(maxi(0, c0 - 3), mini(cols, c0 + 4)):
			var i := _index(c, r)
			if clearance[i] < 0.0:
				continue
			var d := pos.distance_squared_to(Vector2(c, r) * SPACING)
			if distance.size() == clearance.size() and distance[i] >= FAR:
				d += 1.0e6  # prefer a point that can reach the goal
			if d < best_d:
				best_d = d
				best = i
	return best


func _downhill(i: int) -> int:
	var c := i % cols
	@warning_ignore("integer_division")  # the row of a lattice index: whole rows
	var r := i / cols
	var best := i
	for dr: int in [-1, 0, 1]:
		for dc: int in [-1, 0, 1]:
			var nc := c + dc
			var nr := r + dr
			if nc < 0 or nr < 0 or nc >= cols or nr >= rows:
				continue
			var j := _index(nc, nr)
			if distance[j] < distance[best]:
				best = j
	return best
