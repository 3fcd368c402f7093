@tool
extends RefCounted
## Pin arcs as something a designer can edit after placing them: recognises selected field
## pins that lie evenly spaced on one circle (an arc or circle pattern, a hand-made arc) and
## describes them by centre, radius, start and end angle and count; `points` turns such a
## description back into pin centres. Angles are degrees, y down (0 = right, 90 = down), and
## an arc runs from start to end through increasing angles. A whole circle has
## end = start + 360 and no pin at the end (it would sit on the first).

const BoardItems := preload("res://addons/board_editor/core/board_items.gd")

## Fewest pins that make an arc (two pins are a row).
const MIN_PINS := 3
## Largest radius still taken as an arc; flatter runs of pins are rows.
const MAX_RADIUS := 5000.0
## How far (px) a pin may sit off the circle or off even spacing: files round to 0.01 px.
const TOLERANCE := 0.1
## The description's keys, in the order the Selection panel shows them.
const KEYS: Array[String] = ["center_x", "center_y", "radius", "start_deg", "end_deg", "count"]


## The arc the selected items form: the KEYS plus "pins" (the pin indices in arc order), or
## {} when the selection is not only field pins evenly spaced on one circle.
static func of_selection(level: BoardLevel, selection: Array[Vector2i]) -> Dictionary:
	if selection.size() < MIN_PINS:
		return {}
	var indices := PackedInt32Array()
	var points := PackedVector2Array()
	for item in selection:
		if item.x != BoardItems.Kind.PIN or not BoardItems.is_valid(level, item):
			return {}
		if item.y < level.pin_pocket.size() and level.pin_pocket[item.y] >= 0:
			return {}  # a pocket's rim pin moves with its pocket, never on its own
		indices.append(item.y)
		points.append(level.pins[item.y])
	var arc := fit(points)
	if arc.is_empty():
		return {}
	var order: PackedInt32Array = arc["order"]
	var pins := PackedInt32Array()
	for k in order:
		pins.append(indices[k])
	arc.erase("order")
	arc["pins"] = pins
	return arc


## The evenly spaced arc through `points`: the KEYS plus "order" (indices into `points` from
## start to end), or {} when they are not on one circle or not evenly spaced.
static func fit(points: PackedVector2Array) -> Dictionary:
	if points.size() < MIN_PINS:
		return {}
	var circle := _circle_through(points)
	if circle.is_empty():
		return {}
	var center: Vector2 = circle["center"]
	var radius: float = circle["radius"]
	if radius > MAX_RADIUS or radius < TOLERANCE:
		return {}
	var angles: Array[Array] = []
	for i in points.size():
		if absf(points[i].distance_to(center) - radius) > TOLERANCE:
			return {}
		angles.append([rad_to_deg((points[i] - center).angle()), i])
	angles.sort_custom(func(a: Array, b: Array) -> bool: return a[0] < b[0])
	# The arc starts after the widest gap between neighbours (for a whole circle, the gaps
	# are all alike and the arc starts at the first pin by angle).
	var count := angles.size()
	var widest := count - 1
	var widest_gap := _gap(angles, count - 1)
	for i in count - 1:
		if _gap(angles, i) > widest_gap + TOLERANCE / radius:
			widest = i
			widest_gap = _gap(angles, i)
	var first := (widest + 1) % count
	var order := PackedInt32Array()
	for k in count:
		var index: int = angles[(first + k) % count][1]
		order.append(index)
	var start: float = angles[first][0]
	var step := (360.0 - widest_gap) / float(count - 1)
	var closed := absf(widest_gap - step) * deg_to_rad(1.0) * radius <= TOLERANCE
	if closed:
		step = 360.0 / float(count)
	var arc := {
		"center_x": center.x,
		"center_y": center.y,
		"radius": radius,
		"start_deg": start,
		"end_deg": start + (360.0 if closed else step * (count - 1)),
		"count": count,
		"order": order,
	}
	var expected := points_of(arc)
	for k in count:
		if expected[k].distance_to(points[order[k]]) > TOLERANCE * 2.0:
			return {}  # on the circle but not evenly spaced
	return arc


## The pin centres of an arc description (KEYS), start to end.
static func points_of(arc: Dictionary) -> PackedVector2Array:
	var center := Vector2(_number(arc, "center_x"), _number(arc, "center_y"))
	var radius := _number(arc, "radius")
	var start := _number(arc, "start_deg")
	var end := _number(arc, "end_deg")
	var count := int(_number(arc, "count"))
	if absf(end - start) >= 360.0 - 1e-6:
		return PinPatterns.circle(center, radius, count, start)
	return PinPatterns.arc(center, radius, start, end, count)


## The arc's centre, for the centre mark.
static func center_of(arc: Dictionary) -> Vector2:
	return Vector2(_number(arc, "center_x"), _number(arc, "center_y"))


# Degrees from pin i to pin i + 1 by angle (the last wraps round to the first).
static func _gap(angles: Array[Array], i: int) -> float:
	var here: float = angles[i][0]
	var next: float = angles[(i + 1) % angles.size()][0]
	return next - here if i + 1 < angles.size() else next + 360.0 - here


# Least-squares circle (x² + y² + Dx + Ey + F = 0) through points taken about their mean,
# so large coordinates stay precise: {"center", "radius"}, or {} for points in a line.
static func _circle_through(points: PackedVector2Array) -> Dictionary:
	var mean := Vector2.ZERO
	for p in points:
		mean += p
	mean /= float(points.size())
	var suu := 0.0
	var svv := 0.0
	var suv := 0.0
	var suuu := 0.0
	var svvv := 0.0
	var suvv := 0.0
	var svuu := 0.0
	for p in points:
		var d := p - mean
		suu += d.x * d.x
		svv += d.y * d.y
		suv += d.x * d.y
		suuu += d.x * d.x * d.x
		svvv += d.y * d.y * d.y
		suvv += d.x * d.y * d.y
		svuu += d.y * d.x * d.x
	var det := suu * svv - suv * suv
	if absf(det) < 1e-9 * maxf(suu * svv, 1.0):
		return {}
	var bu := 0.5 * (suuu + suvv)
	var bv := 0.5 * (svvv + svuu)
	var uc := (bu * svv - bv * suv) / det
	var vc := (bv * suu - bu * suv) / det
	var radius := sqrt(uc * uc + vc * vc + (suu + svv) / float(points.size()))
	return {"center": mean + Vector2(uc, vc), "radius": radius}


static func _number(arc: Dictionary, key: String) -> float:
	var value: float = arc.get(key, 0.0)
	return value
