class_name PinPatterns
extends RefCounted
## Pin layouts as point lists: rows, staggered lattices, arcs and circles, plus filters to
## keep a layout inside the ring and clear of other features. Used by the shipped boards'
## generator and by the editor's stamp tools. Every function is pure and deterministic.


## `count` points evenly spaced from `from` to `to`, both ends included (one point: `from`).
static func row(from: Vector2, to: Vector2, count: int) -> PackedVector2Array:
	var points := PackedVector2Array()
	if count <= 0:
		return points
	if count == 1:
		points.append(from)
		return points
	for i in count:
		points.append(from.lerp(to, float(i) / float(count - 1)))
	return points


## Rows `spacing.y` apart filling `area`, points `spacing.x` apart in a row; every other row
## is shifted by half a spacing, the classic pachinko stagger. Points on the far edges count.
static func staggered_lattice(area: Rect2, spacing: Vector2) -> PackedVector2Array:
	var points := PackedVector2Array()
	if spacing.x <= 0.0 or spacing.y <= 0.0 or not area.abs().has_area():
		return points
	var rect := area.abs()
	var rows := floori(rect.size.y / spacing.y + 1e-6) + 1
	for r in rows:
		var y := rect.position.y + r * spacing.y
		var x := rect.position.x + (spacing.x * 0.5 if r % 2 == 1 else 0.0)
		while x <= rect.end.x + 1e-6:
			points.append(Vector2(x, y))
			x += spacing.x
	return points


## `count` points on a circular arc from `from_deg` to `to_deg` (degrees, y down, both ends
## included).
static func arc(
	center: Vector2, radius: float, from_deg: float, to_deg: float, count: int
) -> PackedVector2Array:
	var points := PackedVector2Array()
	if count <= 0:
		return points
	var from := deg_to_rad(from_deg)
	var to := deg_to_rad(to_deg)
	for i in count:
		var t := 0.0 if count == 1 else float(i) / float(count - 1)
		var angle := lerpf(from, to, t)
		points.append(center + Vector2(cos(angle), sin(angle)) * radius)
	return points


## `count` points evenly around a whole circle, the first at `start_deg`.
static func circle(
	center: Vector2, radius: float, count: int, start_deg: float = 0.0
) -> PackedVector2Array:
	var points := PackedVector2Array()
	if count <= 0:
		return points
	for i in count:
		var angle := deg_to_rad(start_deg) + TAU * float(i) / float(count)
		points.append(center + Vector2(cos(angle), sin(angle)) * radius)
	return points


## The points no farther than `radius` from `center`.
static func inside_circle(
	points: PackedVector2Array, center: Vector2, radius: float
) -> PackedVector2Array:
	var kept := PackedVector2Array()
	var limit := radius * radius
	for point in points:
		if point.distance_squared_to(center) <= limit:
			kept.append(point)
	return kept


## The points at least `clearance` away from every point of `others` (checked with a
## spatial hash, so big layouts stay fast).
static func away_from(
	points: PackedVector2Array, others: PackedVector2Array, clearance: float
) -> PackedVector2Array:
	if others.is_empty() or clearance <= 0.0:
		return points.duplicate()
	var grid := PointGrid.new(others, clearance)
	var kept := PackedVector2Array()
	var limit := clearance * clearance
	for point in points:
		var clear := true
		for j in grid.near(point):
			if point.distance_squared_to(others[j]) < limit:
				clear = false
				break
		if clear:
			kept.append(point)
	return kept


## The points outside every given rectangle.
static func outside_rects(points: PackedVector2Array, rects: Array[Rect2]) -> PackedVector2Array:
	var kept := PackedVector2Array()
	for point in points:
		var inside := false
		for rect in rects:
			if rect.has_point(point):
				inside = true
				break
		if not inside:
			kept.append(point)
	return kept
