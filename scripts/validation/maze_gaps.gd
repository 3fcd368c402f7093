class_name MazeGaps
extends RefCounted
## BoardValidator's maze gap check: a gap narrower than a ball between two walls, or between
## a wall and the board's edge (the frame), is an error. A ball cannot pass it, but rolls
## into it and wedges there: the autoplay pilot lost whole games to a 5 px gap between a wall
## end and the frame. Walls are binned into a grid first, so only walls near each other are
## compared and a board with thousands of walls still checks in milliseconds.

const ERROR := BoardIssue.Severity.ERROR
## Gaps up to this wide are walls meant to meet (rounding), not gaps, in pixels.
const JOIN_TOLERANCE := 0.5
## The check stops after this many gaps.
const MAX_GAP_ISSUES := 40


## One wall as the physics sees it: a capsule from `a` to `b`; the frame's edges have
## radius 0 and id 0.
class Capsule:
	var a: Vector2
	var b: Vector2
	var radius: float
	var id: int

	func _init(from: Vector2, to: Vector2, half_width: float, wall_id: int) -> void:
		a = from
		b = to
		radius = half_width
		id = wall_id

	func is_frame() -> bool:
		return id == 0


## Adds an error for every gap narrower than a ball (and wider than JOIN_TOLERANCE) between
## two walls or a wall and the frame. Walls with an end that is not a number are skipped
## (MazeChecks reports them).
static func check(level: BoardLevel, issues: Array[BoardIssue]) -> void:
	var shapes := _shapes(level)
	var diameter := level.ball_radius * 2.0
	var cell := maxf(level.path_width + level.wall_width, diameter * 2.0)
	var grid := _bin(shapes, cell, diameter)
	var seen := {}
	var found := 0
	for key: Vector2i in grid:
		var bucket: PackedInt32Array = grid[key]
		for m in bucket.size():
			for n in range(m + 1, bucket.size()):
				var i := mini(bucket[m], bucket[n])
				var j := maxi(bucket[m], bucket[n])
				var pair := Vector2i(i, j)
				if seen.has(pair):
					continue
				seen[pair] = true
				var near: PackedInt32Array = grid[_cell_of(shapes, pair, cell)]
				if _report_gap(level, shapes, pair, near, issues):
					found += 1
					if found >= MAX_GAP_ISSUES:
						return


# Each wall, then the frame's four edges as the physics adds them: zero-width walls along
# the board's border.
static func _shapes(level: BoardLevel) -> Array[Capsule]:
	var shapes: Array[Capsule] = []
	var radius := level.wall_width * 0.5
	@warning_ignore("integer_division")  # walls are pairs of points; a lone end is ignored
	var wall_count := level.walls.size() / 2
	for w in wall_count:
		var a := level.walls[w * 2]
		var b := level.walls[w * 2 + 1]
		if a.is_finite() and b.is_finite():
			shapes.append(Capsule.new(a, b, radius, ItemIds.of(level, "walls", w)))
	var size := level.size
	var corners: Array[Vector2] = [Vector2.ZERO, Vector2(size.x, 0.0), size, Vector2(0.0, size.y)]
	for k in 4:
		shapes.append(Capsule.new(corners[k], corners[(k + 1) % 4], 0.0, 0))
	return shapes


# Grid cell -> the shapes whose box, grown by a ball's width, touches it.
static func _bin(shapes: Array[Capsule], cell: float, reach: float) -> Dictionary:
	var grid := {}
	for s in shapes.size():
		var shape := shapes[s]
		var box := Rect2(shape.a, Vector2.ZERO).expand(shape.b).grow(shape.radius + reach)
		var from := Vector2i(floori(box.position.x / cell), floori(box.position.y / cell))
		var to := Vector2i(floori(box.end.x / cell), floori(box.end.y / cell))
		for y in range(from.y, to.y + 1):
			for x in range(from.x, to.x + 1):
				var bucket: PackedInt32Array = grid.get_or_add(Vector2i(x, y), PackedInt32Array())
				bucket.append(s)
	return grid


# The grid cell of the point where the two shapes of `pair` come closest.
static func _cell_of(shapes: Array[Capsule], pair: Vector2i, cell: float) -> Vector2i:
	var one := shapes[pair.x]
	var other := shapes[pair.y]
	var closest := Geometry2D.get_closest_points_between_segments(one.a, one.b, other.a, other.b)
	var middle := (closest[0] + closest[1]) * 0.5
	return Vector2i(floori(middle.x / cell), floori(middle.y / cell))


# Reports the gap between the two shapes of `pair` when a ball would wedge in it (and no
# third wall fills it: a wall end that meets a border wall is not a gap to the frame behind
# it); true when reported. `near` are the shapes binned where the gap is.
static func _report_gap(
	level: BoardLevel,
	shapes: Array[Capsule],
	pair: Vector2i,
	near: PackedInt32Array,
	issues: Array[BoardIssue]
) -> bool:
	var one := shapes[pair.x]
	var other := shapes[pair.y]
	if one.is_frame() and other.is_frame():
		return false
	var closest := Geometry2D.get_closest_points_between_segments(one.a, one.b, other.a, other.b)
	var p := closest[0]
	var q := closest[1]
	var gap := p.distance_to(q) - one.radius - other.radius
	var diameter := level.ball_radius * 2.0
	if gap <= JOIN_TOLERANCE or gap >= diameter:
		return false
	# The middle of the gap itself, between the two faces.
	var at := p + (q - p).normalized() * (one.radius + gap * 0.5)
	for k in near:
		if k != pair.x and k != pair.y and _covers(shapes[k], at):
			return false
	var what := ""
	if one.is_frame() or other.is_frame():
		var wall := other if one.is_frame() else one
		what = "Wall %d leaves a %.1f px gap to the board's edge" % [wall.id, gap]
	else:
		what = "Walls %d and %d leave a %.1f px gap" % [one.id, other.id, gap]
	(
		BoardIssue
		. add_covering(
			issues,
			ERROR,
			(
				"%s at (%.0f, %.0f): a ball (%.0f px) cannot pass but wedges in it. Close the gap or widen it."
				% [what, at.x, at.y, diameter]
			),
			at,
			"maze_narrow_gap",
			BoardIssue.around(p, diameter, q, diameter)
		)
	)
	return true


# True when `point` lies inside the wall `shape` (or on the frame's line).
static func _covers(shape: Capsule, point: Vector2) -> bool:
	var on := Geometry2D.get_closest_point_to_segment(point, shape.a, shape.b)
	return point.distance_to(on) <= shape.radius + JOIN_TOLERANCE
