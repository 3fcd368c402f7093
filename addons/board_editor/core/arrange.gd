@tool
extends RefCounted
## Align and distribute: the offsets that line the selected items up on one edge or centre
## line, or space them evenly between the outermost two. Items are placed by the point that
## represents them (BoardItems.position_of: a pin's centre, a pocket's mouth, a wall's middle).

const BoardItems := preload("res://addons/board_editor/core/board_items.gd")

## Align modes: the coordinate every item takes.
const ALIGN_MODES: Array[String] = ["left", "center_x", "right", "top", "center_y", "bottom"]


## Item -> offset that aligns `items` by `mode` (one of ALIGN_MODES); items already in
## line are left out.
static func align_offsets(level: BoardLevel, items: Array[Vector2i], mode: String) -> Dictionary:
	var offsets := {}
	var points := _points(level, items)
	if points.size() < 2 or not ALIGN_MODES.has(mode):
		return offsets
	var horizontal := mode in ["left", "center_x", "right"]
	var values: Array[float] = []
	for item: Vector2i in points:
		var at: Vector2 = points[item]
		values.append(at.x if horizontal else at.y)
	var target: float = values.min()
	if mode in ["right", "bottom"]:
		target = values.max()
	elif mode in ["center_x", "center_y"]:
		target = (values.min() + values.max()) * 0.5
	for item: Vector2i in points:
		var at: Vector2 = points[item]
		var offset := Vector2(target - at.x, 0) if horizontal else Vector2(0, target - at.y)
		if not offset.is_zero_approx():
			offsets[item] = offset
	return offsets


## Item -> offset that spaces `items` evenly along `axis` ("x" or "y") between the first and
## the last, keeping their order.
static func distribute_offsets(
	level: BoardLevel, items: Array[Vector2i], axis: String
) -> Dictionary:
	var offsets := {}
	var points := _points(level, items)
	if points.size() < 3:
		return offsets
	var along := 0 if axis == "x" else 1
	var order: Array = points.keys()
	order.sort_custom(
		func(a: Vector2i, b: Vector2i) -> bool: return points[a][along] < points[b][along]
	)
	var first: float = points[order[0]][along]
	var last: float = points[order[order.size() - 1]][along]
	var step := (last - first) / float(order.size() - 1)
	for k in order.size():
		var item: Vector2i = order[k]
		var offset := Vector2.ZERO
		var at: Vector2 = points[item]
		offset[along] = first + step * k - at[along]
		if not offset.is_zero_approx():
			offsets[item] = offset
	return offsets


static func _points(level: BoardLevel, items: Array[Vector2i]) -> Dictionary:
	var points := {}
	for item in items:
		if BoardItems.is_valid(level, item):
			points[item] = BoardItems.position_of(level, item)
	return points
