@tool
extends RefCounted
## The editor's own grid snap (plugins do not get the 2D editor's snap settings) and the
## maze lattice: walls run along cell borders, holes / starts / the goal sit in cells.


## `point` snapped to a square grid of `step` px from the board origin (unchanged when
## `step` is not positive).
static func to_grid(point: Vector2, step: float) -> Vector2:
	if step <= 0.0:
		return point
	return (point / step).round() * step


## The maze's cell pitch: a corridor plus a wall.
static func maze_cell(level: BoardLevel) -> float:
	return level.path_width + level.wall_width


## The nearest crossing of maze grid lines (where walls start and end), inside the grid.
static func to_maze_corner(level: BoardLevel, point: Vector2) -> Vector2:
	var cell := maze_cell(level)
	if cell <= 0.0:
		return point
	var col := clampf(roundf(point.x / cell), 0, level.grid_cols)
	var row := clampf(roundf(point.y / cell), 0, level.grid_rows)
	return Vector2(col, row) * cell


## The centre of the maze cell under `point`, inside the grid.
static func to_maze_cell_center(level: BoardLevel, point: Vector2) -> Vector2:
	var cell := maze_cell(level)
	if cell <= 0.0:
		return point
	var col := clampf(floorf(point.x / cell), 0, maxi(level.grid_cols - 1, 0))
	var row := clampf(floorf(point.y / cell), 0, maxi(level.grid_rows - 1, 0))
	return (Vector2(col, row) + Vector2(0.5, 0.5)) * cell


## A wall from `a` to `b` forced along one grid axis (the longer one), as maze walls are.
static func straighten(a: Vector2, b: Vector2) -> Vector2:
	var d := b - a
	return Vector2(b.x, a.y) if absf(d.x) >= absf(d.y) else Vector2(a.x, b.y)
