class_name MazeChecks
extends RefCounted
## BoardValidator's maze checks: grid, walls, starts, goal, holes, and whether every ball
## can roll from its start to the goal (a flood fill on a fine grid where the walls are
## grown by the ball radius, so a cell is free exactly where a ball's centre fits).

const ERROR := BoardIssue.Severity.ERROR
const WARNING := BoardIssue.Severity.WARNING
## Below this a wall counts as zero length, in pixels.
const MIN_WALL_LENGTH := 0.01


## Reachability always runs when it can: other errors do not hide a boxed-in goal. When it
## cannot (no usable grid, goal or starts; a wall end that is not a number), a warning says
## it was skipped and why.
static func check(level: BoardLevel, issues: Array[BoardIssue]) -> void:
	if not _check_shape(level, issues):
		_skipped_reachability(
			"the maze's grid, walls, goal or starts have the errors above", issues
		)
		return
	if not MazeLimits.check(level, issues):
		_skipped_reachability("the maze is past the size limits above", issues)
		return
	var walls_ok := _check_walls(level, issues)
	var bad_starts := _check_points(level, issues)
	MazeGaps.check(level, issues)
	if not walls_ok:
		_skipped_reachability("a wall has an end that is not a number", issues)
		return
	_check_reachability(level, bad_starts, issues)


static func _skipped_reachability(why: String, issues: Array[BoardIssue]) -> void:
	BoardIssue.add_to(
		issues,
		WARNING,
		"Whether every ball can roll to the goal was not checked: %s." % why,
		Vector2.ZERO,
		"reachability_skipped"
	)


static func _check_shape(level: BoardLevel, issues: Array[BoardIssue]) -> bool:
	var ok := true
	if level.grid_cols < 1 or level.grid_rows < 1:
		BoardIssue.add_to(
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
		BoardIssue.add_to(
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
		BoardIssue.add_to(
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
		BoardIssue.add_to(
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
		BoardIssue.add_to(
			issues,
			ERROR,
			"Black holes need a positive radius (got %s)." % level.hole_radius,
			Vector2.ZERO,
			"bad_hole"
		)
		ok = false
	if level.ball_starts.is_empty():
		BoardIssue.add_to(issues, ERROR, "The maze has no ball starts.", Vector2.ZERO, "no_starts")
		ok = false
	return ok


# Every wall a number, longer than zero and on the board; false when an end is not a number.
static func _check_walls(level: BoardLevel, issues: Array[BoardIssue]) -> bool:
	var finite := true
	var area := _board_rect(level).grow(0.5)
	@warning_ignore("integer_division")  # walls are pairs of points; a lone end is ignored
	var wall_count := level.walls.size() / 2
	for w in wall_count:
		var a := level.walls[w * 2]
		var b := level.walls[w * 2 + 1]
		if not a.is_finite() or not b.is_finite():
			finite = false
			BoardIssue.add_to(
				issues,
				ERROR,
				"Wall %d has an end that is not a number." % ItemIds.of(level, "walls", w),
				Vector2.ZERO,
				"not_finite"
			)
		elif a.distance_to(b) < MIN_WALL_LENGTH:
			BoardIssue.add_to(
				issues,
				ERROR,
				(
					"Wall %d at (%.0f, %.0f) has zero length."
					% [ItemIds.of(level, "walls", w), a.x, a.y]
				),
				a,
				"wall_zero_length"
			)
		elif not area.has_point(a) or not area.has_point(b):
			BoardIssue.add_to(
				issues,
				ERROR,
				"Wall %d runs off the board." % ItemIds.of(level, "walls", w),
				a if not area.has_point(a) else b,
				"wall_outside"
			)
	return finite


# The goal, starts and holes; returns the starts with an error of their own (reachability
# leaves them out rather than report them twice).
static func _check_points(level: BoardLevel, issues: Array[BoardIssue]) -> Dictionary:
	var area := _board_rect(level)
	_check_goal_fits(level, area, issues)
	var bad_starts := {}
	for i in level.ball_starts.size():
		var before := _error_count(issues)
		_check_start(level, area, i, issues)
		if _error_count(issues) > before:
			bad_starts[i] = true
		_check_start_overlaps(level, i, issues)
	_check_holes(level, area, issues)
	return bad_starts


static func _error_count(issues: Array[BoardIssue]) -> int:
	return issues.filter(func(issue: BoardIssue) -> bool: return issue.is_error()).size()


# Ball start i: a number, on the board, clear of walls and holes, not already in the goal.
static func _check_start(level: BoardLevel, area: Rect2, i: int, issues: Array[BoardIssue]) -> void:
	var s := level.ball_starts[i]
	var reach := level.wall_width * 0.5 + level.ball_radius
	if not s.is_finite():
		BoardIssue.add_to(
			issues,
			ERROR,
			"Ball start %d is not a number." % ItemIds.of(level, "ball_starts", i),
			Vector2.ZERO,
			"not_finite"
		)
	elif not area.grow(-level.ball_radius).has_point(s):
		BoardIssue.add_to(
			issues,
			ERROR,
			(
				"Ball start %d at (%.0f, %.0f) is off the board."
				% [ItemIds.of(level, "ball_starts", i), s.x, s.y]
			),
			s,
			"start_outside"
		)
	elif _nearest_wall_distance(level, s) < reach - 0.01:
		BoardIssue.add_to(
			issues,
			ERROR,
			(
				"Ball start %d at (%.0f, %.0f) is inside a wall."
				% [ItemIds.of(level, "ball_starts", i), s.x, s.y]
			),
			s,
			"start_in_wall"
		)
	elif _in_any(level.holes, level.hole_radius, s):
		BoardIssue.add_to(
			issues,
			ERROR,
			(
				"Ball start %d is in a black hole: hard mode would be lost at once."
				% ItemIds.of(level, "ball_starts", i)
			),
			s,
			"start_in_hole"
		)
	elif s.distance_to(level.goal_center) < level.goal_radius:
		BoardIssue.add_to(
			issues,
			WARNING,
			"Ball start %d is already in the goal." % ItemIds.of(level, "ball_starts", i),
			s,
			"start_in_goal"
		)


# Ball start i against every earlier one: two balls may not spawn inside each other.
static func _check_start_overlaps(level: BoardLevel, i: int, issues: Array[BoardIssue]) -> void:
	var s := level.ball_starts[i]
	for j in i:
		if s.distance_to(level.ball_starts[j]) < level.ball_radius * 2.0:
			var text := "Ball starts %d and %d overlap: the balls would spawn inside each other."
			var ids := [ItemIds.of(level, "ball_starts", j), ItemIds.of(level, "ball_starts", i)]
			var both := BoardIssue.around(
				s, level.ball_radius, level.ball_starts[j], level.ball_radius
			)
			BoardIssue.add_covering(issues, ERROR, text % ids, s, "starts_overlap", both)


# Every black hole on the board and clear of the goal.
static func _check_holes(level: BoardLevel, area: Rect2, issues: Array[BoardIssue]) -> void:
	for h in level.holes.size():
		var p := level.holes[h]
		if not p.is_finite() or not area.has_point(p):
			BoardIssue.add_to(
				issues,
				ERROR,
				"Black hole %d is not on the board." % ItemIds.of(level, "holes", h),
				Vector2.ZERO if not p.is_finite() else p,
				"bad_hole"
			)
		elif p.distance_to(level.goal_center) < level.goal_radius + level.hole_radius:
			BoardIssue.add_covering(
				issues,
				WARNING,
				"Black hole %d overlaps the goal." % ItemIds.of(level, "holes", h),
				p,
				"hole_in_goal",
				BoardIssue.around(p, level.hole_radius, level.goal_center, level.goal_radius)
			)


static func _check_reachability(
	level: BoardLevel, bad_starts: Dictionary, issues: Array[BoardIssue]
) -> void:
	var fill := MazeFlood.new(level, false)
	for cause in MazeEnclosure.causes(level, fill, bad_starts):
		issues.append(
			MazeEnclosureIssue.of(level, cause, level.ball_starts.size() - bad_starts.size())
		)
	if level.holes.is_empty():
		return
	var hard := MazeFlood.new(level, true, fill.free)
	for i in level.ball_starts.size():
		if bad_starts.has(i):
			continue
		if fill.reaches_goal(level.ball_starts[i]) and not hard.reaches_goal(level.ball_starts[i]):
			BoardIssue.add_covering(
				issues,
				WARNING,
				(
					"In hard mode, black holes cut ball start %d off from the goal."
					% ItemIds.of(level, "ball_starts", i)
				),
				level.ball_starts[i],
				"holes_block_goal",
				BoardIssue.around(
					level.ball_starts[i], level.ball_radius, level.goal_center, level.goal_radius
				)
			)


# The centre is on the board (checked above), but the ring can still hang over the edge:
# then part of the goal is unreachable and it is drawn off the board.
static func _check_goal_fits(level: BoardLevel, area: Rect2, issues: Array[BoardIssue]) -> void:
	var c := level.goal_center
	if area.grow(-level.goal_radius).has_point(c):
		return
	(
		BoardIssue
		. add_covering(
			issues,
			WARNING,
			(
				"The goal at (%.1f, %.1f) with radius %.1f hangs off the board; move it inwards or shrink it."
				% [c.x, c.y, level.goal_radius]
			),
			c,
			"goal_off_board",
			BoardIssue.around(c, level.goal_radius, c, level.goal_radius)
		)
	)


static func _board_rect(level: BoardLevel) -> Rect2:
	return Rect2(Vector2.ZERO, level.size)


static func _nearest_wall_distance(level: BoardLevel, p: Vector2) -> float:
	var best := INF
	@warning_ignore("integer_division")  # walls are pairs of points; a lone end is ignored
	var wall_count := level.walls.size() / 2
	for w in wall_count:
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
