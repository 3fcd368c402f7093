extends RefCounted
## BoardValidator's maze checks: grid, walls, starts, goal, holes, and whether every ball
## can roll from its start to the goal (a flood fill on a fine grid where the walls are
## grown by the ball radius, so a cell is free exactly where a ball's centre fits).

const ERROR := BoardIssue.Severity.ERROR
const WARNING := BoardIssue.Severity.WARNING
## The flood fill grid has at most about this many cells (keeps live validation fast).
const MAX_CELLS := 40000.0
## Below this a wall counts as zero length, in pixels.
const MIN_WALL_LENGTH := 0.01


static func check(level: BoardLevel, issues: Array[BoardIssue]) -> void:
	if not _check_shape(level, issues):
		return
	_check_walls(level, issues)
	_check_points(level, issues)
	if issues.any(func(issue: BoardIssue) -> bool: return issue.is_error()):
		return  # reachability needs sane walls and starts
	_check_reachability(level, issues)


static func _check_shape(level: BoardLevel, issues: Array[BoardIssue]) -> bool:
	var ok := true
	if level.grid_cols < 1 or level.grid_rows < 1:
		_add(
			issues,
			ERROR,
			(
				"The maze grid needs at least one column and row (got %d × %d)."
				% [level.grid_cols, level.grid_rows]
			),
			Vector2.ZERO,
			"bad_grid"
		)
		ok = false
	if (
		not is_finite(level.path_width)
		or not is_finite(level.wall_width)
		or level.path_width <= 0.0
		or level.wall_width <= 0.0
	):
		_add(
			issues,
			ERROR,
			(
				"Path and wall widths must be positive (got %s and %s)."
				% [level.path_width, level.wall_width]
			),
			Vector2.ZERO,
			"bad_grid"
		)
		ok = false
	if level.walls.size() % 2 != 0:
		_add(
			issues,
			ERROR,
			"Walls are stored as point pairs, but there are %d points." % level.walls.size(),
			Vector2.ZERO,
			"odd_wall_points"
		)
		ok = false
	var center := level.goal_center
	if (
		not center.is_finite()
		or not is_finite(level.goal_radius)
		or level.goal_radius <= level.ball_radius
		or not _board_rect(level).has_point(center)
	):
		_add(
			issues,
			ERROR,
			(
				"The goal needs a centre on the board and a radius above the ball's (got %s, %s)."
				% [center, level.goal_radius]
			),
			center if center.is_finite() else Vector2.ZERO,
			"bad_goal"
		)
		ok = false
	if (
		not level.holes.is_empty()
		and (not is_finite(level.hole_radius) or level.hole_radius <= 0.0)
	):
		_add(
			issues,
			ERROR,
			"Black holes need a positive radius (got %s)." % level.hole_radius,
			Vector2.ZERO,
			"bad_hole"
		)
		ok = false
	if level.ball_starts.is_empty():
		_add(issues, ERROR, "The maze has no ball starts.", Vector2.ZERO, "no_starts")
		ok = false
	return ok


static func _check_walls(level: BoardLevel, issues: Array[BoardIssue]) -> void:
	var area := _board_rect(level).grow(0.5)
	for w in level.walls.size() / 2:
		var a := level.walls[w * 2]
		var b := level.walls[w * 2 + 1]
		if not a.is_finite() or not b.is_finite():
			_add(
				issues,
				ERROR,
				"Wall %d has an end that is not a number." % w,
				Vector2.ZERO,
				"not_finite"
			)
		elif a.distance_to(b) < MIN_WALL_LENGTH:
			_add(
				issues,
				ERROR,
				"Wall %d at (%.0f, %.0f) has zero length." % [w, a.x, a.y],
				a,
				"wall_zero_length"
			)
		elif not area.has_point(a) or not area.has_point(b):
			_add(
				issues,
				ERROR,
				"Wall %d runs off the board." % w,
				a if not area.has_point(a) else b,
				"wall_outside"
			)


static func _check_points(level: BoardLevel, issues: Array[BoardIssue]) -> void:
	var area := _board_rect(level)
	var reach := level.wall_width * 0.5 + level.ball_radius
	for i in level.ball_starts.size():
		var s := level.ball_starts[i]
		if not s.is_finite():
			_add(issues, ERROR, "Ball start %d is not a number." % i, Vector2.ZERO, "not_finite")
		elif not area.grow(-level.ball_radius).has_point(s):
			_add(
				issues,
				ERROR,
				"Ball start %d at (%.0f, %.0f) is off the board." % [i, s.x, s.y],
				s,
				"start_outside"
			)
		elif _nearest_wall_distance(level, s) < reach - 0.01:
			_add(
				issues,
				ERROR,
				"Ball start %d at (%.0f, %.0f) is inside a wall." % [i, s.x, s.y],
				s,
				"start_in_wall"
			)
		elif _in_any(level.holes, level.hole_radius, s):
			_add(
				issues,
				ERROR,
				"Ball start %d is in a black hole: hard mode would be lost at once." % i,
				s,
				"start_in_hole"
			)
		elif s.distance_to(level.goal_center) < level.goal_radius:
			_add(issues, WARNING, "Ball start %d is already in the goal." % i, s, "start_in_goal")
		for j in i:
			if s.distance_to(level.ball_starts[j]) < level.ball_radius * 2.0:
				var text := "Ball starts %d and %d overlap: the balls would spawn inside each other."
				_add(issues, ERROR, text % [j, i], s, "starts_overlap")
	for h in level.holes.size():
		var p := level.holes[h]
		if not p.is_finite() or not area.has_point(p):
			_add(
				issues,
				ERROR,
				"Black hole %d is not on the board." % h,
				Vector2.ZERO if not p.is_finite() else p,
				"bad_hole"
			)
		elif p.distance_to(level.goal_center) < level.goal_radius + level.hole_radius:
			_add(issues, WARNING, "Black hole %d overlaps the goal." % h, p, "hole_in_goal")


static func _check_reachability(level: BoardLevel, issues: Array[BoardIssue]) -> void:
	var fill := MazeFlood.new(level, false)
	for i in level.ball_starts.size():
		if not fill.reaches_goal(level.ball_starts[i]):
			_add(
				issues,
				ERROR,
				"Ball start %d cannot roll to the goal: walls close it in." % i,
				level.ball_starts[i],
				"start_cannot_reach_goal"
			)
	if level.holes.is_empty():
		return
	var hard := MazeFlood.new(level, true, fill)
	for i in level.ball_starts.size():
		if fill.reaches_goal(level.ball_starts[i]) and not hard.reaches_goal(level.ball_starts[i]):
			_add(
				issues,
				WARNING,
				"In hard mode, black holes cut ball start %d off from the goal." % i,
				level.ball_starts[i],
				"holes_block_goal"
			)


static func _board_rect(level: BoardLevel) -> Rect2:
	return Rect2(Vector2.ZERO, level.size)


static func _nearest_wall_distance(level: BoardLevel, p: Vector2) -> float:
	var best := INF
	for w in level.walls.size() / 2:
		var q := Geometry2D.get_closest_point_to_segment(
			p, level.walls[w * 2], level.walls[w * 2 + 1]
		)
		best = minf(best, p.distance_to(q))
	return best


static func _in_any(points: PackedVector2Array, radius: float, p: Vector2) -> bool:
	for q in points:
		if p.distance_to(q) < radius:
			return true
	return false


static func _add(
	issues: Array[BoardIssue],
	severity: BoardIssue.Severity,
	text: String,
	at: Vector2,
	code: String
) -> void:
	issues.append(BoardIssue.new(severity, text, at, code))


## Free space of a maze for a ball's centre, on a grid; answers "can this start reach the
## goal?" with connected regions labelled once.
class MazeFlood:
	extends RefCounted
	var cell: float
	var cols: int
	var rows: int
	var free := PackedByteArray()
	var region := PackedInt32Array()
	var goal_regions := {}
	var _level: BoardLevel

	## Free space of `level`; with `holes_block` the black holes count as blocked. `base`, a
	## flood of the same level without holes, lends its wall grid (the costly part).
	func _init(level: BoardLevel, holes_block: bool, base: MazeFlood = null) -> void:
		_level = level
		cell = maxf(level.ball_radius * 0.75, sqrt(level.size.x * level.size.y / MAX_CELLS))
		cols = maxi(1, ceili(level.size.x / cell))
		rows = maxi(1, ceili(level.size.y / cell))
		free.resize(cols * rows)
		free.fill(1)
		region.resize(cols * rows)
		region.fill(-1)
		if base != null and base.cols == cols and base.rows == rows:
			free = base.free.duplicate()
		else:
			_block_edges()
			var grow := level.wall_width * 0.5 + level.ball_radius - minf(0.5, cell * 0.25)
			for w in level.walls.size() / 2:
				_block_capsule(level.walls[w * 2], level.walls[w * 2 + 1], grow)
		if holes_block:
			for hole in level.holes:
				_block_capsule(hole, hole, level.hole_radius)
		_label_regions()

	func reaches_goal(start: Vector2) -> bool:
		var index := _index_of(start)
		return index >= 0 and goal_regions.has(region[index])

	func _index_of(p: Vector2) -> int:
		var cx := floori(p.x / cell)
		var cy := floori(p.y / cell)
		if cx < 0 or cy < 0 or cx >= cols or cy >= rows:
			return -1
		return cy * cols + cx

	# Cells whose centre is closer than a ball radius to the board's edge.
	func _block_edges() -> void:
		var r := _level.ball_radius
		var x_lo := ceili(r / cell - 0.5)
		var x_hi := floori((_level.size.x - r) / cell - 0.5)
		var y_lo := ceili(r / cell - 0.5)
		var y_hi := floori((_level.size.y - r) / cell - 0.5)
		for cy in rows:
			for cx in cols:
				if cx < x_lo or cx > x_hi or cy < y_lo or cy > y_hi:
					free[cy * cols + cx] = 0

	func _block_capsule(a: Vector2, b: Vector2, grow: float) -> void:
		var box := Rect2(a, Vector2.ZERO).expand(b).grow(grow)
		var x0 := maxi(0, floori(box.position.x / cell))
		var y0 := maxi(0, floori(box.position.y / cell))
		var x1 := mini(cols - 1, floori(box.end.x / cell))
		var y1 := mini(rows - 1, floori(box.end.y / cell))
		var grow2 := grow * grow
		var ab := b - a
		var len2 := ab.length_squared()
		for cy in range(y0, y1 + 1):
			var py := (cy + 0.5) * cell
			for cx in range(x0, x1 + 1):
				var px := (cx + 0.5) * cell
				var t := 0.0
				if len2 > 0.0:
					t = clampf(((px - a.x) * ab.x + (py - a.y) * ab.y) / len2, 0.0, 1.0)
				var dx := px - (a.x + ab.x * t)
				var dy := py - (a.y + ab.y * t)
				if dx * dx + dy * dy < grow2:
					free[cy * cols + cx] = 0

	func _label_regions() -> void:
		var label := 0
		var queue := PackedInt32Array()
		queue.resize(free.size())
		var goal := _level.goal_center
		var goal2 := _level.goal_radius * _level.goal_radius
		for start in _level.ball_starts:
			var seed_index := _index_of(start)
			if seed_index < 0 or free[seed_index] == 0 or region[seed_index] >= 0:
				continue
			region[seed_index] = label
			queue[0] = seed_index
			var head := 0
			var tail := 1
			while head < tail:
				var index := queue[head]
				head += 1
				var cx := index % cols
				var cy := index / cols
				var gx := (cx + 0.5) * cell - goal.x
				var gy := (cy + 0.5) * cell - goal.y
				if gx * gx + gy * gy < goal2:
					goal_regions[label] = true
				for k in 4:
					var n := index
					if k == 0 and cx > 0:
						n = index - 1
					elif k == 1 and cx < cols - 1:
						n = index + 1
					elif k == 2 and cy > 0:
						n = index - cols
					elif k == 3 and cy < rows - 1:
						n = index + cols
					if n != index and free[n] == 1 and region[n] < 0:
						region[n] = label
						queue[tail] = n
						tail += 1
			label += 1
