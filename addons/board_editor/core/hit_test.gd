@tool
extends RefCounted
## Static picking on a board: which item is under a point, which items are in a box, and
## which ring / rail / goal handle is under a point. All in board pixels.

const Items := preload("res://addons/board_editor/core/board_items.gd")
const PinChecks := preload("res://scripts/validation/pin_checks.gd")

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


## The item under `point` (within `tolerance` px of its shape), nearest first; NONE if
## nothing is there. A click inside a pin, hole or ball start picks it even over a wall. A
## pocket's rim pins pick the pocket; a bonus pocket is picked inside its cup (rim pins
## included), a windmill inside the circle its blades sweep.
static func pick(level: BoardLevel, point: Vector2, tolerance: float) -> Vector2i:
	var best := Items.NONE
	var best_distance := INF
	for i in level.pins.size():
		var gap := level.pins[i].distance_to(point) - level.pin_radius
		if gap <= tolerance and gap < best_distance:
			best_distance = gap
			var owner := level.pin_pocket[i] if i < level.pin_pocket.size() else -1
			best = Items.make(Items.Kind.POCKET, owner) if owner >= 0 else Vector2i(0, i)
	for i in level.pockets.size():
		if _pocket_rect(level.pockets[i]).grow(tolerance).has_point(point):
			var gap := level.pockets[i].position.distance_to(point) * 0.5
			if gap < best_distance:
				best_distance = gap
				best = Items.make(Items.Kind.POCKET, i)
	for i in level.holes.size():
		var gap := level.holes[i].distance_to(point) - level.hole_radius
		if gap <= tolerance and gap < best_distance:
			best_distance = gap
			best = Items.make(Items.Kind.HOLE, i)
	for i in level.ball_starts.size():
		var gap := level.ball_starts[i].distance_to(point) - level.ball_radius
		if gap <= tolerance and gap < best_distance:
			best_distance = gap
			best = Items.make(Items.Kind.START, i)
	for w in Items.wall_count(level.walls):
		var closest := Geometry2D.get_closest_point_to_segment(
			point, level.walls[w * 2], level.walls[w * 2 + 1]
		)
		var gap := closest.distance_to(point) - level.wall_width * 0.5
		# A start, hole or pin drawn over a wall wins a click inside it: the wall is bigger
		# and can be picked anywhere else along its length.
		if gap <= tolerance and gap < best_distance and best_distance > 0.0:
			best_distance = gap
			best = Items.make(Items.Kind.WALL, w)
	for i in level.bonus_pockets.size():
		var spec := level.bonus_pockets[i]
		if spec != null and BonusChecks.cup_rect(level, spec).grow(tolerance).has_point(point):
			var gap := spec.position.distance_to(point) * 0.5
			if gap < best_distance:
				best_distance = gap
				best = Items.make(Items.Kind.BONUS, i)
	for i in level.windmills.size():
		var spec := level.windmills[i]
		if spec == null:
			continue
		# Inside the sweep; nearer the pin counts as nearer (blades are thin and turn).
		var gap := spec.position.distance_to(point) - spec.sweep_radius()
		if gap <= tolerance and gap * 0.5 < best_distance:
			best_distance = gap * 0.5
			best = Items.make(Items.Kind.WINDMILL, i)
	if level.is_maze() and best == Items.NONE:
		# The goal is big: only its middle picks it, so walls and starts inside stay reachable.
		if level.goal_center.distance_to(point) <= maxf(tolerance, level.goal_radius * 0.35):
			best = Items.make(Items.Kind.GOAL, 0)
	return best


## Every item a brush of radius `tolerance` touches as it sweeps from `from` to `to` (a
## capsule round the segment), pockets once: what an erase drag passes over, however far
## apart the mouse events that bound the stroke. The goal is never in it.
static func along(
	level: BoardLevel, from: Vector2, to: Vector2, tolerance: float
) -> Array[Vector2i]:
	var found: Array[Vector2i] = []
	for i in level.pins.size():
		if _reach(level.pins[i], from, to) <= level.pin_radius + tolerance:
			var owner := level.pin_pocket[i] if i < level.pin_pocket.size() else -1
			var item := Items.make(Items.Kind.POCKET, owner) if owner >= 0 else Vector2i(0, i)
			if not found.has(item):
				found.append(item)
	for i in level.pockets.size():
		var item := Items.make(Items.Kind.POCKET, i)
		if (
			not found.has(item)
			and _crosses(_pocket_rect(level.pockets[i]).grow(tolerance), from, to)
		):
			found.append(item)
	for w in Items.wall_count(level.walls):
		var ends := Geometry2D.get_closest_points_between_segments(
			from, to, level.walls[w * 2], level.walls[w * 2 + 1]
		)
		if ends[0].distance_to(ends[1]) <= level.wall_width * 0.5 + tolerance:
			found.append(Items.make(Items.Kind.WALL, w))
	for i in level.holes.size():
		if _reach(level.holes[i], from, to) <= level.hole_radius + tolerance:
			found.append(Items.make(Items.Kind.HOLE, i))
	for i in level.ball_starts.size():
		if _reach(level.ball_starts[i], from, to) <= level.ball_radius + tolerance:
			found.append(Items.make(Items.Kind.START, i))
	for i in level.bonus_pockets.size():
		var spec := level.bonus_pockets[i]
		if spec != null and _crosses(BonusChecks.cup_rect(level, spec).grow(tolerance), from, to):
			found.append(Items.make(Items.Kind.BONUS, i))
	for i in level.windmills.size():
		var wheel := level.windmills[i]
		if wheel != null and _reach(wheel.position, from, to) <= wheel.sweep_radius() + tolerance:
			found.append(Items.make(Items.Kind.WINDMILL, i))
	return found


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


## A pocket's body as a box: the mouth's width, from the mouth down to the special pin.
static func _pocket_rect(spec: PocketSpec) -> Rect2:
	return Rect2(spec.position - Vector2(spec.width * 0.5, 0), Vector2(spec.width, spec.depth))


# How near the segment from `from` to `to` comes to `point`.
static func _reach(point: Vector2, from: Vector2, to: Vector2) -> float:
	return Geometry2D.get_closest_point_to_segment(point, from, to).distance_to(point)


# True when the segment from `from` to `to` touches `box` (an end inside, or an edge crossed).
static func _crosses(box: Rect2, from: Vector2, to: Vector2) -> bool:
	if box.has_point(from) or box.has_point(to):
		return true
	var corners: Array[Vector2] = [box.position, Vector2(box.end.x, box.position.y), box.end]
	corners.append(Vector2(box.position.x, box.end.y))
	for k in 4:
		var hit: Variant = Geometry2D.segment_intersects_segment(
			from, to, corners[k], corners[(k + 1) % 4]
		)
		if hit != null:
			return true
	return false
