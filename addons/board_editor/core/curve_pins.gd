@tool
extends RefCounted
## Pins along a drawn curve (PeggleEdit's peg line): the mouse path is a polyline, and the
## pins are spaced evenly along its length, either `count` of them from end to end or one
## every `spacing` pixels from the start.


## The length of the polyline `path`.
static func length_of(path: PackedVector2Array) -> float:
	var total := 0.0
	for i in range(1, path.size()):
		total += path[i - 1].distance_to(path[i])
	return total


## Pins along `path`: with `count` > 0 exactly that many, first and last on the ends; with
## `count` 0 one every `spacing` px (at least 1 px). An empty path gives none.
static func along(path: PackedVector2Array, count: int, spacing: float) -> PackedVector2Array:
	var pins := PackedVector2Array()
	if path.is_empty():
		return pins
	var total := length_of(path)
	if total <= 0.0 or count == 1:
		pins.append(path[0])
		return pins
	var step := total / float(count - 1) if count > 1 else maxf(spacing, 1.0)
	var wanted := count if count > 1 else int(floorf(total / step + 1e-6)) + 1
	var segment := 1
	var walked := 0.0  # length of the path before `segment`
	for k in wanted:
		var target := minf(step * k, total)
		while segment < path.size() - 1 and walked + _piece(path, segment) < target:
			walked += _piece(path, segment)
			segment += 1
		var piece := _piece(path, segment)
		var t := (target - walked) / piece if piece > 0.0 else 0.0
		pins.append(path[segment - 1].lerp(path[segment], clampf(t, 0.0, 1.0)))
	return pins


static func _piece(path: PackedVector2Array, segment: int) -> float:
	return path[segment - 1].distance_to(path[segment])
