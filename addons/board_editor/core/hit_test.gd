@tool
extends RefCounted
## Static picking on a board: which item is under a point, which items are in a box, and
## which ring / rail / goal handle is under a point. All in board pixels.

const BoardItems := preload("res://addons/board_editor/core/board_items.gd")

## Handle names are the BoardLevel fields they edit.
const PACHINKO_HANDLES: Array[String] = [
	"ring_center",
	"ring_radius",
	"rail_start_deg",
	"rail_end_deg",
	"rail_width",
	"gutter_start_deg",
	"gutter_end_deg",
]
const MAZE_HANDLES: Array[String] = ["goal_radius"]


## The item under `point` (within `tolerance` px of its outline, ItemOutline.of_item),
## nearest first; NONE if nothing is there. A click inside a pin, hole or ball start picks
## it even over a wall (PickRank.UNDER); the goal only when nothing else is there
## (PickRank.LAST). A pocket's rim pins pick the pocket; a bonus pocket is picked inside its
## cup (rim pins included), a windmill inside the circle its blades sweep.
static func pick(level: BoardLevel, point: Vector2, tolerance: float) -> Vector2i:
	var best := BoardItems.NONE
	var best_distance := INF
	for rank: int in ItemKind.PickRank.values():
		for kind in ItemKinds.all():
			if kind.pick_rank != rank or not _may_pick(rank, best, best_distance):
				continue
			for index in kind.field_indices(level):
				if not kind.is_valid(level, index):
					continue
				var distance := ItemOutline.of_item(kind, level, index).pick_distance(
					point, tolerance
				)
				if distance < best_distance and _may_pick(rank, best, best_distance):
					best_distance = distance
					best = _picked(level, kind, index)
	return best


## Every item a brush of radius `tolerance` touches as it sweeps from `from` to `to` (a
## capsule round the segment), each once (a pocket however many of its pins are touched):
## what an erase drag passes over, however far apart the mouse events that bound the
## stroke. What the eraser leaves alone (the goal) is never in it.
static func along(
	level: BoardLevel, from: Vector2, to: Vector2, tolerance: float
) -> Array[Vector2i]:
	var found: Array[Vector2i] = []
	for kind in ItemKinds.all():
		if not kind.erasable:
			continue
		for index in kind.field_indices(level):
			if kind.is_valid(level, index):
				var item := _picked(level, kind, index)
				var touched := ItemOutline.of_item(kind, level, index).touches(from, to, tolerance)
				if touched and not found.has(item):
					found.append(item)
	return found


# True when an item of `rank` may still take the pick from `best`: a wall only from nothing
# or from an item the click is outside of, the goal only from nothing.
static func _may_pick(rank: int, best: Vector2i, best_distance: float) -> bool:
	match rank:
		ItemKind.PickRank.UNDER:
			return best_distance > 0.0
		ItemKind.PickRank.LAST:
			return best == BoardItems.NONE
	return true


# The item a designer gets for entry `index` of `kind`: itself, or its owner (a rim pin's
# pocket).
static func _picked(level: BoardLevel, kind: ItemKind, index: int) -> Vector2i:
	if kind.is_item(level, index):
		return Vector2i(kind.pick, index)
	return kind.owner.call(level, index)


## True when a pin ghost at `point` shows red: a click there would crowd a pin, or put it
## outside the ring or in the launch rail (the validator's errors, PinChecks.where_outside).
static func pin_blocked(level: BoardLevel, point: Vector2) -> bool:
	return crowds_pin(level, point) or not PinChecks.where_outside(level, point).is_empty()


## True when a new pin at `point` would overlap a pin of `level` or leave it a gap narrower
## than a ball (the validator's overlap and narrow-gap warnings): ghosts turn red there.
static func crowds_pin(level: BoardLevel, point: Vector2) -> bool:
	var reach := level.pin_radius * 2.0 + level.ball_radius * 2.0
	for pin in level.pins:
		if pin.distance_squared_to(point) < reach * reach:
			return true
	return false


## Every item whose representative point lies inside `rect` (a pocket once, however many of
## its pins are inside; a wall when both its ends are inside; a bonus pocket by its mouth).
static func in_rect(level: BoardLevel, rect: Rect2) -> Array[Vector2i]:
	var box := rect.abs()
	var found: Array[Vector2i] = []
	for item in ItemKinds.items_of(level):
		var kind := ItemKinds.of_item(level, item)
		var inside := true
		for point in kind.box_points(level, item.y):
			inside = inside and box.has_point(point)
		if not inside:
			continue
		if not kind.is_item(level, item.y):
			item = kind.owner.call(level, item.y)  # a rim pin boxes its pocket
		if not found.has(item):
			found.append(item)
	return found


static func handle_points(level: BoardLevel) -> Dictionary[String, Vector2]:
	var points: Dictionary[String, Vector2] = {}
	if level.is_maze():
		points["goal_radius"] = level.goal_center + Vector2(level.goal_radius, 0)
		return points
	var c := level.ring_center
	var r := level.ring_radius
	points["ring_center"] = c
	points["ring_radius"] = c + Vector2.from_angle(PI * 1.25) * r
	points["rail_start_deg"] = c + Vector2.from_angle(deg_to_rad(level.rail_start_deg)) * r
	points["rail_end_deg"] = c + Vector2.from_angle(deg_to_rad(level.rail_end_deg)) * r
	var middle := deg_to_rad((level.rail_start_deg + level.rail_end_deg) * 0.5)
	points["rail_width"] = c + Vector2.from_angle(middle) * (r - level.rail_width)
	points["gutter_start_deg"] = c + Vector2.from_angle(deg_to_rad(level.gutter_start_deg)) * r
	points["gutter_end_deg"] = c + Vector2.from_angle(deg_to_rad(level.gutter_end_deg)) * r
	return points


## The handle under `point`, or "" when none is within `tolerance`.
static func pick_handle(level: BoardLevel, point: Vector2, tolerance: float) -> String:
	var points := handle_points(level)
	var best := ""
	var best_distance := tolerance
	for handle: String in points:
		var distance := points[handle].distance_to(point)
		if distance <= best_distance:
			best_distance = distance
			best = handle
	return best


## The value a handle takes when dragged to `point`. Angles stay within half a turn of
## their old value so a rail that crosses 0 degrees does not jump by 360.
static func handle_value(level: BoardLevel, handle: String, point: Vector2) -> Variant:
	match handle:
		"ring_center":
			return point
		"ring_radius":
			return maxf(level.ring_center.distance_to(point), 1.0)
		"rail_width":
			var inner := level.ring_center.distance_to(point)
			return clampf(level.ring_radius - inner, 1.0, level.ring_radius * 0.5)
		"goal_radius":
			return maxf(level.goal_center.distance_to(point), 1.0)
	var old: float = level.get(handle)
	var angle := rad_to_deg((point - level.ring_center).angle())
	return old + wrapf(angle - old, -180.0, 180.0)
