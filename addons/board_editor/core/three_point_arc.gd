@tool
extends RefCounted
## A pin arc by three points a designer can see and drag: its two ends and a bulge point the
## arc passes through. `through` turns them into PinArc's description (centre, radius,
## start and end angle), the arc starting at the first end; `handles` gives the three points
## back (the bulge at the arc's middle). Three points in a line bend no arc: refused with a
## message that says so.

## Least bend, px: a bulge point nearer the line between the ends than this is "in a line".
const MIN_BEND := 0.5


## The arc from `a` through `bulge` to `b` with `count` pins: PinArc.KEYS ("center_x",
## "center_y", "radius", "start_deg" at `a`, "end_deg" at `b`, "count"), or {"error": why}
## when the points are in a line or two of them meet.
static func through(a: Vector2, bulge: Vector2, b: Vector2, count: int) -> Dictionary:
	if a.distance_to(b) < MIN_BEND:
		return {"error": "The arc's two ends are at the same place: drag one end away."}
	var chord := b - a
	var bend := absf(chord.cross(bulge - a)) / chord.length()
	if bend < MIN_BEND or bulge.distance_to(a) < MIN_BEND or bulge.distance_to(b) < MIN_BEND:
		return {
			"error":
			"The arc's ends and bulge point are in a line: move the bulge point off the line to bend it."
		}
	var center := _circumcentre(a, bulge, b)
	var start := rad_to_deg((a - center).angle())
	var to_bulge := fposmod(rad_to_deg((bulge - center).angle()) - start, 360.0)
	var to_end := fposmod(rad_to_deg((b - center).angle()) - start, 360.0)
	# The way round from a that meets the bulge before b: increasing angles, or decreasing.
	var sweep := to_end if to_bulge < to_end else to_end - 360.0
	return {
		"center_x": center.x,
		"center_y": center.y,
		"radius": a.distance_to(center),
		"start_deg": start,
		"end_deg": start + sweep,
		"count": count,
	}


## The arc's handles: [first end, bulge (the arc's middle), last end].
static func handles(arc: Dictionary) -> PackedVector2Array:
	var center := Vector2(_number(arc, "center_x"), _number(arc, "center_y"))
	var radius := _number(arc, "radius")
	var start := deg_to_rad(_number(arc, "start_deg"))
	var end := deg_to_rad(_number(arc, "end_deg"))
	var middle := (start + end) * 0.5
	return PackedVector2Array(
		[
			center + Vector2.from_angle(start) * radius,
			center + Vector2.from_angle(middle) * radius,
			center + Vector2.from_angle(end) * radius,
		]
	)


# The centre of the circle through three points not in a line.
static func _circumcentre(a: Vector2, b: Vector2, c: Vector2) -> Vector2:
	var ab := b - a
	var ac := c - a
	var d := 2.0 * ab.cross(ac)
	var ux := (ac.y * ab.length_squared() - ab.y * ac.length_squared()) / d
	var uy := (ab.x * ac.length_squared() - ac.x * ab.length_squared()) / d
	return a + Vector2(ux, uy)


static func _number(arc: Dictionary, key: String) -> float:
	var value: float = arc.get(key, 0.0)
	return value
