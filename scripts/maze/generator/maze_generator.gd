@tool
class_name MazeGenerator
extends RefCounted
## Builds a playable maze board from MazeGenSettings: the tutorial's 35 px cells, an open
## 2 × 2 goal room in the middle, a random perfect maze carved from it with some walls
## knocked out for loops (fewer on harder mazes), a ball start in each corner and black
## holes that never cut a start off from the goal. The result is ordinary board data (walls,
## starts, goal, holes) that BoardValidator accepts; the same settings always give the same
## board.

## A cell: a 25 px corridor and a 10 px wall, as in the tutorial.
const CELL := 35.0
const PATH_WIDTH := 25.0
const WALL_WIDTH := 10.0
const BALL_RADIUS := 5.0
## The goal ring fits inside the 2 × 2 goal room with its dashed line clear of the room's
## walls: the floor paints the line RING_LINE px wide just outside the radius, and the walls'
## faces stand 35 − 5 = 30 px from the centre: 24 + 5 leaves a pixel between them.
const GOAL_RADIUS := 24.0
## The room kept for the goal's drawn edge outside its radius (px; the floor shader's dish
## lip, goal_line, is 2).
const RING_LINE := 5.0
const HOLE_RADIUS := 9.0
## Share of the inner walls knocked out at difficulty 0 and at difficulty 1.
const OPENNESS_EASY := 0.35
const OPENNESS_HARD := 0.08


## Builds the maze `settings` ask for. Returns {"level": BoardLevel, "holes_placed": int}
## or {"error": "what is wrong"}.
static func generate(settings: MazeGenSettings) -> Dictionary:
	if settings == null:
		return {"error": "The maze generator needs its settings."}
	var problem := settings.problem()
	if not problem.is_empty():
		return {"error": problem}
	var rng := RandomNumberGenerator.new()
	rng.seed = settings.rng_seed
	var carver := MazeCarver.new(settings.cols, settings.rows)
	carver.carve(rng, lerpf(OPENNESS_EASY, OPENNESS_HARD, settings.difficulty))
	var level := base_level(settings)
	var walls := PackedVector2Array()
	for wall in carver.wall_segments():
		walls.append(wall[0] * CELL)
		walls.append(wall[1] * CELL)
	level.walls = walls
	level.goal_center = Vector2(carver.room + Vector2i.ONE) * CELL
	var last := Vector2(settings.cols - 1, settings.rows - 1)
	var starts := PackedVector2Array()
	for corner: Vector2 in [Vector2.ZERO, Vector2(last.x, 0), Vector2(0, last.y), last]:
		starts.append((corner + Vector2(0.5, 0.5)) * CELL)
	level.ball_starts = starts
	var placed := MazeHolePlacer.place(
		level, carver, CELL, settings.holes, settings.difficulty, rng
	)
	var crossing := wall_in_goal_ring(level)
	if crossing >= 0:
		var a: Vector2 = level.walls[crossing * 2]
		var b: Vector2 = level.walls[crossing * 2 + 1]
		return {
			"error":
			"A wall from (%d, %d) to (%d, %d) crosses the goal ring." % [a.x, a.y, b.x, b.y]
		}
	for issue in BoardValidator.validate(level):
		if issue.is_error() or issue.kind == "holes_block_goal":
			return {"error": "The generated maze failed its check: %s" % issue.message}
	return {"level": level, "holes_placed": placed}


## The index of the first wall of `level` that reaches into its goal ring (the circle and
## its RING_LINE px line outside it), or -1 when the ring is clear.
static func wall_in_goal_ring(level: BoardLevel) -> int:
	var reach := level.goal_radius + RING_LINE + level.wall_width * 0.5
	for w in range(level.walls.size() >> 1):
		var near := Geometry2D.get_closest_point_to_segment(
			level.goal_center, level.walls[w * 2], level.walls[w * 2 + 1]
		)
		if near.distance_to(level.goal_center) < reach:
			return w
	return -1


## A maze board of the settings' size with no walls, starts or holes yet.
static func base_level(settings: MazeGenSettings) -> BoardLevel:
	var level := BoardLevel.new()
	level.kind = BoardLevel.Kind.MAZE
	level.board_id = "maze_" + settings.id
	level.display_name = settings.title
	level.description = settings.blurb
	level.size = Vector2(settings.cols, settings.rows) * CELL
	level.ball_radius = BALL_RADIUS
	level.tuning = TuningPresets.maze()
	level.grid_cols = settings.cols
	level.grid_rows = settings.rows
	level.path_width = PATH_WIDTH
	level.wall_width = WALL_WIDTH
	level.goal_radius = GOAL_RADIUS
	level.hole_radius = HOLE_RADIUS
	return level
