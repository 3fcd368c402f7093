@tool
class_name ItemOutline
extends RefCounted
## The outline of one board item as the editor picks it, sweeps it with an eraser and frames
## it when selected: a circle (a pin, a hole, a windmill's sweep, the goal), a box (a
## pocket's or a bonus pocket's cup) or a capsule (a wall). An ItemKind row makes one per
## item (ItemKind.outline_of), so the editor's hit test and selection frame loop over the
## table instead of switching on the kind.

enum Form { CIRCLE, BOX, CAPSULE }

## Which shape this is.
var form := Form.CIRCLE
## CIRCLE: the centre; BOX: the point that ranks a pick (a pocket's mouth); CAPSULE: end A.
var center := Vector2.ZERO
## CIRCLE: the radius; CAPSULE: half the width.
var radius := 0.0
## BOX: the box.
var box := Rect2()
## CAPSULE: end B.
var end := Vector2.ZERO
## How far a pick's distance counts (0.5: a windmill's thin blades, nearer its pin counts
## as nearer).
var weight := 1.0
## More than 0: only a click within this share of the radius (or the pick tolerance) picks
## it, so the big goal leaves what lies inside it reachable.
var core := 0.0
## How far the selection frame stands outside the outline (a pocket's rim pins).
var margin := 0.0
## Drawn as a ring, not a disc (big things: the goal, a windmill's sweep), this wide (px).
var hollow := false
var line_width := 1.5


## The outline of an item of `kind` whose value is `value` (ItemKind.value_of, or what a
## click would place): the row's `outlines` hook, else a POINT kind's circle or a SEGMENT
## kind's capsule, `size_field` the radius or the width.
static func of_value(kind: ItemKind, level: BoardLevel, value: Variant) -> ItemOutline:
	if kind.outlines.is_valid():
		return kind.outlines.call(level, value)
	var size: float = level.get(kind.size_field) if not kind.size_field.is_empty() else 0.0
	if kind.shape == ItemKind.Shape.SEGMENT:
		var pair: Array = value
		var a: Vector2 = pair[0]
		var b: Vector2 = pair[1]
		return capsule(a, b, size)
	if value is Vector2:
		var point: Vector2 = value
		return circle(point, size)
	var spec: Resource = value
	var at: Vector2 = spec.get("position")
	return circle(at, size)


## The outline of item `index` of `kind` on `level`.
static func of_item(kind: ItemKind, level: BoardLevel, index: int) -> ItemOutline:
	return of_value(kind, level, kind.value_of(level, index))


## A circle of `of_radius` round `at`.
static func circle(at: Vector2, of_radius: float) -> ItemOutline:
	var outline := ItemOutline.new()
	outline.center = at
	outline.radius = of_radius
	return outline


## A box whose picks rank by the distance to `anchor`, halved (the box is big).
static func boxed(area: Rect2, anchor: Vector2) -> ItemOutline:
	var outline := ItemOutline.new()
	outline.form = Form.BOX
	outline.box = area
	outline.center = anchor
	outline.weight = 0.5
	return outline


## A capsule `width` wide round the segment from `a` to `b`.
static func capsule(a: Vector2, b: Vector2, width: float) -> ItemOutline:
	var outline := ItemOutline.new()
	outline.form = Form.CAPSULE
	outline.center = a
	outline.end = b
	outline.radius = width * 0.5
	return outline


## How near `point` a click picks this item (less is nearer; a click inside is 0 or less),
## or INF when `point` is not within `tolerance` of it.
func pick_distance(point: Vector2, tolerance: float) -> float:
	match form:
		Form.BOX:
			if box.grow(tolerance).has_point(point):
				return center.distance_to(point) * weight
			return INF
		Form.CAPSULE:
			var closest := Geometry2D.get_closest_point_to_segment(point, center, end)
			var gap := closest.distance_to(point) - radius
			return gap * weight if gap <= tolerance else INF
	if core > 0.0:
		var inner := maxf(tolerance, radius * core)
		return 0.0 if center.distance_to(point) <= inner else INF
	var outside := center.distance_to(point) - radius
	return outside * weight if outside <= tolerance else INF


## True when a brush of radius `tolerance` sweeping from `from` to `to` touches this item.
func touches(from: Vector2, to: Vector2, tolerance: float) -> bool:
	match form:
		Form.BOX:
			return _crosses(box.grow(tolerance), from, to)
		Form.CAPSULE:
			var ends := Geometry2D.get_closest_points_between_segments(from, to, center, end)
			return ends[0].distance_to(ends[1]) <= radius + tolerance
	var closest := Geometry2D.get_closest_point_to_segment(center, from, to)
	return closest.distance_to(center) <= radius + tolerance


# True when the segment from `from` to `to` touches `area` (an end inside, or an edge crossed).
static func _crosses(area: Rect2, from: Vector2, to: Vector2) -> bool:
	if area.has_point(from) or area.has_point(to):
		return true
	var corners: Array[Vector2] = [area.position, Vector2(area.end.x, area.position.y), area.end]
	corners.append(Vector2(area.position.x, area.end.y))
	for k in 4:
		var hit: Variant = Geometry2D.segment_intersects_segment(
			from, to, corners[k], corners[(k + 1) % 4]
		)
		if hit != null:
			return true
	return false
