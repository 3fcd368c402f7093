class_name MazeLimits
extends RefCounted
## The size limits a maze must keep before the costly checks run (the flood fill, the
## distances from every start and hole to every wall) and before the game builds it: a file
## may hold thousands of walls that all cross the board, which no real maze needs and which
## would make the checks and every physics step crawl. Each limit is measured in what a real
## maze needs, so the work of the later checks follows the board's size, not the file's.
## Limits (README "Safety"): the item lists of board_schema.gd (walls, holes, starts), plus
## - all walls together at most WALL_LENGTH_GRIDS times the length of a wall on every edge
##   of the board's grid (a maze with every wall in place has exactly one such length);
## - at most MAX_WALLS_PER_AREA walls crossing any one area of the grid's pitch (path plus
##   wall width; the shipped mazes have at most 3 there);
## - at most MAX_HOLES_PER_CELL black holes per grid cell on average.

const ERROR := BoardIssue.Severity.ERROR
## All walls together may be this many times as long as a wall on every grid edge.
const WALL_LENGTH_GRIDS := 1.5
## Most walls that may cross one area of the grid's pitch.
const MAX_WALLS_PER_AREA := 12
## Most black holes per grid cell, on average over the board.
const MAX_HOLES_PER_CELL := 1.0
## The crowding count uses at most about this many areas (larger boards use larger areas).
const MAX_AREAS := 4096.0


## Adds an error to `issues` and returns false when `level` (a maze whose grid, widths and
## wall pairs are sane) is past a limit; the costly checks must not run then.
static func check(level: BoardLevel, issues: Array[BoardIssue]) -> bool:
	var cells := level.grid_cols * level.grid_rows
	if level.holes.size() > ceili(cells * MAX_HOLES_PER_CELL):
		var text := (
			"The maze has %d black holes; a %d × %d grid takes at most %d."
			% [level.holes.size(), level.grid_cols, level.grid_rows, cells]
		)
		BoardIssue.add_to(issues, ERROR, text, Vector2.ZERO, "too_many_holes")
		return false
	var full_grid := full_grid_length(level)
	var total := total_wall_length(level)
	if total > full_grid * WALL_LENGTH_GRIDS:
		var text := (
			(
				"The walls are %.0f px long together; this board's grid takes at most %.0f px"
				+ " (%.1f × a wall on every grid edge)."
			)
			% [total, full_grid * WALL_LENGTH_GRIDS, WALL_LENGTH_GRIDS]
		)
		BoardIssue.add_to(issues, ERROR, text, Vector2.ZERO, "too_much_wall")
		return false
	var crowded := _most_crowded(level)
	if crowded.z > MAX_WALLS_PER_AREA:
		var text := (
			"%d walls cross one spot near (%.0f, %.0f); at most %d may."
			% [crowded.z, crowded.x, crowded.y, MAX_WALLS_PER_AREA]
		)
		BoardIssue.add_to(issues, ERROR, text, Vector2(crowded.x, crowded.y), "walls_crowded")
		return false
	return true


## The length of a wall on every edge of the board's grid: grid_rows + 1 lines across and
## grid_cols + 1 lines down.
static func full_grid_length(level: BoardLevel) -> float:
	return (level.grid_rows + 1) * level.size.x + (level.grid_cols + 1) * level.size.y


## All walls' lengths together (an end that is not a number counts as nothing here; the
## wall checks name it).
static func total_wall_length(level: BoardLevel) -> float:
	var total := 0.0
	@warning_ignore("integer_division")  # walls are pairs of points
	for w in level.walls.size() / 2:
		var length := level.walls[w * 2].distance_to(level.walls[w * 2 + 1])
		if is_finite(length):
			total += length
	return total


# The area crossed by the most walls: Vector3(x, y, count) of its centre. Each wall is
# walked in half-area steps (the total length is already bounded, so this is too).
static func _most_crowded(level: BoardLevel) -> Vector3:
	var area := maxf(
		level.path_width + level.wall_width, sqrt(level.size.x * level.size.y / MAX_AREAS)
	)
	var cols := maxi(1, ceili(level.size.x / area))
	var rows := maxi(1, ceili(level.size.y / area))
	var counts := PackedInt32Array()
	counts.resize(cols * rows)
	var most := Vector3.ZERO
	var seen := {}
	@warning_ignore("integer_division")  # walls are pairs of points
	for w in level.walls.size() / 2:
		var a := level.walls[w * 2]
		var b := level.walls[w * 2 + 1]
		if not a.is_finite() or not b.is_finite():
			continue
		seen.clear()
		var steps := ceili(a.distance_to(b) / (area * 0.5))
		for step in steps + 1:
			var p := a.lerp(b, float(step) / maxf(1.0, steps))
			var cx := floori(p.x / area)
			var cy := floori(p.y / area)
			if cx < 0 or cy < 0 or cx >= cols or cy >= rows or seen.has(cy * cols + cx):
				continue
			var index := cy * cols + cx
			seen[index] = true
			counts[index] += 1
			if counts[index] > most.z:
				most = Vector3((cx + 0.5) * area, (cy + 0.5) * area, counts[index])
	return most
