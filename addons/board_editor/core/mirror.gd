@tool
extends RefCounted
## Left-right mirror mode: reflections across a vertical axis, and the "partner" of an item
## (the item at its mirrored place) so one edit lands on both halves of the board.

const BoardItems := preload("res://addons/board_editor/core/board_items.gd")

## Two points closer than this (px) are the same place.
const SAME_PLACE := 0.5


## The axis mirror mode reflects across: the ring's centre line on a pachinko board, the
## middle of the board on a maze.
static func axis_of(level: BoardLevel) -> float:
	return level.ring_center.x if level.is_pachinko() else level.size.x * 0.5


## `point` reflected across the vertical line x = `axis`.
static func reflect(point: Vector2, axis: float) -> Vector2:
	return ItemKind.reflect(point, axis)


## `points` plus their reflections, leaving out reflections that land on a point already
## there (points on the axis are their own reflection).
static func with_reflections(points: PackedVector2Array, axis: float) -> PackedVector2Array:
	var result := points.duplicate()
	for point in points:
		var mirrored := reflect(point, axis)
		if not _has_point(result, mirrored):
			result.append(mirrored)
	return result


## An item set (see BoardItems.extract) plus its mirror image: each kind's items, then the
## reflections that land where none of them is (an item on the axis stays single); a
## mirrored windmill turns the other way.
static func mirror_set(data: Dictionary, axis: float) -> Dictionary:
	var result := data.duplicate(true)
	for kind in ItemKinds.set_rows():
		var values := BoardItems.set_values(data, kind)
		var step := 2 if kind.shape == ItemKind.Shape.SEGMENT else 1
		var kept: Array = []
		for value: Variant in values:
			kept.append(kind.moved_value(value, Vector2.ZERO))
		for i in range(0, values.size() - step + 1, step):
			var twin: Array = []
			for k in step:
				twin.append(kind.reflected_value(values[i + k], axis))
			if _find_item(kept, twin, step) < 0:
				kept.append_array(twin)
		result[kind.set_key] = BoardItems.set_entry(kind, kept)
	return result


## The mirror image of an item set alone (the originals left out): what "Mirror to the
## other half" adds. Windmill twins turn the other way.
static func reflections_of(data: Dictionary, axis: float) -> Dictionary:
	var result := BoardItems.empty_set()
	for kind in ItemKinds.set_rows():
		var reflected: Array = []
		for value: Variant in BoardItems.set_values(data, kind):
			reflected.append(kind.reflected_value(value, axis))
		result[kind.set_key] = BoardItems.set_entry(kind, reflected)
	return result


## The item at `item`'s mirrored place: itself when it sits on the axis, NONE when the
## other half has nothing there. The goal has no partner.
static func partner(level: BoardLevel, item: Vector2i, axis: float) -> Vector2i:
	var kind := ItemKinds.of_item(level, item)
	if kind == null or not kind.is_valid(level, item.y) or kind.shape == ItemKind.Shape.SINGLE:
		return BoardItems.NONE
	if kind.shape == ItemKind.Shape.SEGMENT:
		var ends: PackedVector2Array = level.get(kind.field)
		var a := reflect(ends[item.y * 2], axis)
		var b := reflect(ends[item.y * 2 + 1], axis)
		var found := _find_wall(ends, a, b)
		return BoardItems.NONE if found < 0 else BoardItems.make(kind.pick, found)
	var target := reflect(kind.position_of(level, item.y), axis)
	for i in kind.field_indices(level):
		if not kind.is_item(level, i):
			continue
		if kind.position_of(level, i).distance_to(target) <= SAME_PLACE:
			return BoardItems.make(kind.pick, i)
	return BoardItems.NONE


## The items plus their partners (for erasing both halves).
static func with_partners(
	level: BoardLevel, items: Array[Vector2i], axis: float
) -> Array[Vector2i]:
	var result: Array[Vector2i] = items.duplicate()
	for item in items:
		var other := partner(level, item, axis)
		if other != BoardItems.NONE and not result.has(other):
			result.append(other)
	return result


## Splits a selection for a mirrored move: {direct, mirrored, on_axis}. Items on the side of
## `anchor_x` (the grabbed item) follow the mouse, their partners follow its reflection, and
## items on the axis only move up and down so they stay on it.
static func split_for_move(
	level: BoardLevel, items: Array[Vector2i], axis: float, anchor_x: float
) -> Dictionary:
	var anchor_side := -1.0 if anchor_x <= axis else 1.0
	var direct: Array[Vector2i] = []
	var mirrored: Array[Vector2i] = []
	var on_axis: Array[Vector2i] = []
	for item in items:
		var other := partner(level, item, axis)
		if other == item:
			on_axis.append(item)
		elif other == BoardItems.NONE:
			direct.append(item)
		else:
			var side := signf(BoardItems.position_of(level, item).x - axis)
			if items.has(other) and side != anchor_side:
				continue
			direct.append(item)
			if not mirrored.has(other):
				mirrored.append(other)
	return {"direct": direct, "mirrored": mirrored, "on_axis": on_axis}


static func _has_point(points: PackedVector2Array, point: Vector2) -> bool:
	for other in points:
		if other.distance_to(point) <= SAME_PLACE:
			return true
	return false


static func _find_wall(walls: PackedVector2Array, a: Vector2, b: Vector2) -> int:
	for w in BoardItems.wall_count(walls):
		var p := walls[w * 2]
		var q := walls[w * 2 + 1]
		var same := p.distance_to(a) <= SAME_PLACE and q.distance_to(b) <= SAME_PLACE
		var flipped := p.distance_to(b) <= SAME_PLACE and q.distance_to(a) <= SAME_PLACE
		if same or flipped:
			return w
	return -1


# The index of the item in `values` (`step` entries each: a point, a wall's two ends in
# either order, a resource by its position) that `twin` lands on, or -1.
static func _find_item(values: Array, twin: Array, step: int) -> int:
	for i in range(0, values.size() - step + 1, step):
		if step == 2:
			var ends := PackedVector2Array([values[i], values[i + 1]])
			var a: Vector2 = twin[0]
			var b: Vector2 = twin[1]
			if _find_wall(ends, a, b) == 0:
				return i
		elif _place(values[i]).distance_to(_place(twin[0])) <= SAME_PLACE:
			return i
	return -1


# Where an item-set value stands: a point, or a resource's position.
static func _place(value: Variant) -> Vector2:
	if value is Vector2:
		return value
	var spec: Resource = value
	var at: Vector2 = spec.get("position")
	return at
