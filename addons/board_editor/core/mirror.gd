@tool
extends RefCounted
## Left-right mirror mode: reflections across a vertical axis, and the "partner" of an item
## (the item at its mirrored place) so one edit lands on both halves of the board.

const Items := preload("res://addons/board_editor/core/board_items.gd")

## Two points closer than this (px) are the same place.
const SAME_PLACE := 0.5


## The axis mirror mode reflects across: the ring's centre line on a pachinko board, the
## middle of the board on a maze.
static func axis_of(level: BoardLevel) -> float:
	return level.ring_center.x if level.is_pachinko() else level.size.x * 0.5


## `point` reflected across the vertical line x = `axis`.
static func reflect(point: Vector2, axis: float) -> Vector2:
	return Vector2(2.0 * axis - point.x, point.y)


## `points` plus their reflections, leaving out reflections that land on a point already
## there (points on the axis are their own reflection).
static func with_reflections(points: PackedVector2Array, axis: float) -> PackedVector2Array:
	var result := points.duplicate()
	for point in points:
		var mirrored := reflect(point, axis)
		if not _has_point(result, mirrored):
			result.append(mirrored)
	return result


## An item set (see BoardItems.extract) plus its mirror image.
static func mirror_set(data: Dictionary, axis: float) -> Dictionary:
	var result := data.duplicate(true)
	for key: String in ["pins", "holes", "starts"]:
		var points: PackedVector2Array = data.get(key, PackedVector2Array())
		result[key] = with_reflections(points, axis)
	var walls: PackedVector2Array = data.get("walls", PackedVector2Array())
	var all_walls := walls.duplicate()
	for i in range(0, walls.size() - 1, 2):
		var a := reflect(walls[i], axis)
		var b := reflect(walls[i + 1], axis)
		if _find_wall(all_walls, a, b) < 0:
			all_walls.append(a)
			all_walls.append(b)
	result["walls"] = all_walls
	var pockets: Array = []
	var spots := PackedVector2Array()
	for spec: PocketSpec in data.get("pockets", []):
		pockets.append(PocketSpec.create(spec.position, spec.width, spec.depth, spec.payout))
		spots.append(spec.position)
	for spec: PocketSpec in data.get("pockets", []):
		var mirrored := reflect(spec.position, axis)
		if not _has_point(spots, mirrored):
			spots.append(mirrored)
			pockets.append(PocketSpec.create(mirrored, spec.width, spec.depth, spec.payout))
	result["pockets"] = pockets
	var bonus: Array = []
	var bonus_spots := PackedVector2Array()
	for spec: BonusPocketSpec in data.get("bonus", []):
		bonus.append(Items.moved_bonus(spec, Vector2.ZERO))
		bonus_spots.append(spec.position)
	for spec: BonusPocketSpec in data.get("bonus", []):
		var mirrored := reflect(spec.position, axis)
		if not _has_point(bonus_spots, mirrored):
			bonus_spots.append(mirrored)
			bonus.append(Items.moved_bonus(spec, mirrored - spec.position))
	result["bonus"] = bonus
	var wheels: Array = data.get("windmills", [])
	result["windmills"] = _mirrored_windmills(wheels, axis)
	return result


## The mirror image of an item set alone (the originals left out): what "Mirror to the
## other half" adds. Windmill twins turn the other way.
static func reflections_of(data: Dictionary, axis: float) -> Dictionary:
	var result := Items.empty_set()
	for key: String in ["pins", "walls", "holes", "starts"]:
		var points: PackedVector2Array = data.get(key, PackedVector2Array())
		var reflected := PackedVector2Array()
		for point in points:
			reflected.append(reflect(point, axis))
		result[key] = reflected
	var pockets: Array = result["pockets"]
	for spec: PocketSpec in data.get("pockets", []):
		var at := reflect(spec.position, axis)
		pockets.append(PocketSpec.create(at, spec.width, spec.depth, spec.payout))
	var bonus: Array = result["bonus"]
	for spec: BonusPocketSpec in data.get("bonus", []):
		bonus.append(Items.moved_bonus(spec, reflect(spec.position, axis) - spec.position))
	var wheels: Array = result["windmills"]
	for spec: WindmillSpec in data.get("windmills", []):
		var twin := spec.moved(reflect(spec.position, axis) - spec.position)
		twin.speed = -spec.speed
		wheels.append(twin)
	return result


# The windmills and their mirror images, which turn the other way (a mirrored board plays
# the same from both sides); one on the axis stays single.
static func _mirrored_windmills(wheels: Array, axis: float) -> Array:
	var result: Array = []
	var spots := PackedVector2Array()
	for spec: WindmillSpec in wheels:
		result.append(spec.moved(Vector2.ZERO))
		spots.append(spec.position)
	for spec: WindmillSpec in wheels:
		var mirrored := reflect(spec.position, axis)
		if not _has_point(spots, mirrored):
			spots.append(mirrored)
			var twin := spec.moved(mirrored - spec.position)
			twin.speed = -spec.speed
			result.append(twin)
	return result


## The item at `item`'s mirrored place: itself when it sits on the axis, NONE when the
## other half has nothing there. The goal has no partner.
static func partner(level: BoardLevel, item: Vector2i, axis: float) -> Vector2i:
	if not Items.is_valid(level, item) or item.x == Items.Kind.GOAL:
		return Items.NONE
	if item.x == Items.Kind.WALL:
		var a := reflect(level.walls[item.y * 2], axis)
		var b := reflect(level.walls[item.y * 2 + 1], axis)
		var found := _find_wall(level.walls, a, b)
		return Items.NONE if found < 0 else Items.make(Items.Kind.WALL, found)
	var target := reflect(Items.position_of(level, item), axis)
	var count := 0
	match item.x:
		Items.Kind.PIN:
			count = level.pins.size()
		Items.Kind.POCKET:
			count = level.pockets.size()
		Items.Kind.HOLE:
			count = level.holes.size()
		Items.Kind.START:
			count = level.ball_starts.size()
		Items.Kind.BONUS:
			count = level.bonus_pockets.size()
		Items.Kind.WINDMILL:
			count = level.windmills.size()
	for i in count:
		var other := Vector2i(item.x, i)
		if item.x == Items.Kind.PIN and level.pin_pocket.size() > i and level.pin_pocket[i] >= 0:
			continue
		if item.x == Items.Kind.BONUS and not _same_role(level, item.y, i):
			continue
		if Items.position_of(level, other).distance_to(target) <= SAME_PLACE:
			return other
	return Items.NONE


## The items plus their partners (for erasing both halves).
static func with_partners(
	level: BoardLevel, items: Array[Vector2i], axis: float
) -> Array[Vector2i]:
	var result: Array[Vector2i] = items.duplicate()
	for item in items:
		var other := partner(level, item, axis)
		if other != Items.NONE and not result.has(other):
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
		elif other == Items.NONE:
			direct.append(item)
		else:
			var side := signf(Items.position_of(level, item).x - axis)
			if items.has(other) and side != anchor_side:
				continue
			direct.append(item)
			if not mirrored.has(other):
				mirrored.append(other)
	return {"direct": direct, "mirrored": mirrored, "on_axis": on_axis}


# True when bonus pockets `a` and `b` have the same role (a tulip's partner is a tulip).
static func _same_role(level: BoardLevel, a: int, b: int) -> bool:
	var first := level.bonus_pockets[a]
	var second := level.bonus_pockets[b]
	return first != null and second != null and first.role == second.role


static func _has_point(points: PackedVector2Array, point: Vector2) -> bool:
	for other in points:
		if other.distance_to(point) <= SAME_PLACE:
			return true
	return false


static func _find_wall(walls: PackedVector2Array, a: Vector2, b: Vector2) -> int:
	for w in Items.wall_count(walls):
		var p := walls[w * 2]
		var q := walls[w * 2 + 1]
		var same := p.distance_to(a) <= SAME_PLACE and q.distance_to(b) <= SAME_PLACE
		var flipped := p.distance_to(b) <= SAME_PLACE and q.distance_to(a) <= SAME_PLACE
		if same or flipped:
			return w
	return -1
