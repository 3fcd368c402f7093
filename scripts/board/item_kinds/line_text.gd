@tool
class_name LineText
extends RefCounted
## How an item line of a board file writes and reads its values: numbers rounded to
## PRECISION without trailing zeros, coordinates as named pairs (`"x": 12, "y": 4.5`). The
## kind files build their lines with it, and BoardTextWriter writes its fields with `number`,
## so every number in a file is written one way.

## Coordinates and sizes are written to this precision (px).
const PRECISION := 0.01


## `value` rounded to PRECISION, written without trailing zeros ("12", "12.5", "-0.25").
static func number(value: float) -> String:
	var rounded := snappedf(value, PRECISION)
	if rounded == 0.0:
		return "0"  # never "-0"
	if rounded == floorf(rounded) and absf(rounded) < 1e15:
		return str(int(rounded))
	return String.num(rounded, 2)


## `"x": 1, "y": 2` for `points` named by `keys` in pairs (a wall: ax, ay, bx, by).
static func coords(keys: Array, points: PackedVector2Array) -> String:
	var parts := PackedStringArray()
	for k in points.size():
		var p := points[k]
		parts.append(
			'"%s": %s, "%s": %s' % [keys[k * 2], number(p.x), keys[k * 2 + 1], number(p.y)]
		)
	return ", ".join(parts)


## The points a checked line names by `keys` in pairs.
static func points_of(line: Dictionary, keys: Array) -> PackedVector2Array:
	var points := PackedVector2Array()
	for i: int in range(0, keys.size() - 1, 2):
		points.append(Vector2(float_of(line[keys[i]]), float_of(line[keys[i + 1]])))
	return points


## A checked JSON number as a float (typed, so no unsafe conversion warning).
static func float_of(value: Variant) -> float:
	var number_value: float = value
	return number_value


## A checked JSON number as an int (a float is cut toward zero, as int() does).
static func int_of(value: Variant) -> int:
	var whole: int = value
	return whole
