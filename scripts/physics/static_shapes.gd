class_name StaticShapes
extends RefCounted
## The static shapes of a BallWorld as flat arrays (pins, capsule walls, the ring and its
## drain arc, sensor circles) and the checked calls that add them. StaticGeometry owns one
## and bins it into its grid. Internal to scripts/physics.

## Sensor kinds (see add_sensor).
const SENSOR_HOLE := 0
const SENSOR_GOAL := 1
const SENSOR_ZONE := 2
## Goals and zones are tracked per ball in one int bit mask each.
const MAX_SENSORS := 31

var pin_pos := PackedVector2Array()
var pin_radius := PackedFloat32Array()
## A tag the pin's owner gives it (-1: none), reported when the pin captures a ball.
var pin_tag := PackedInt32Array()
## 1 for a pin that captures (removes) a ball that touches it.
var pin_captures := PackedByteArray()
## Material: the least horizontal speed (px/s) a ball keeps after touching the pin.
var pin_min_speed_x := PackedFloat64Array()

var wall_a := PackedVector2Array()
var wall_b := PackedVector2Array()
var wall_radius := PackedFloat32Array()
## b - a, and 1 / |b - a|² (0 for a zero-length wall, which acts as a round pin).
var wall_ab := PackedVector2Array()
var wall_inv_len2 := PackedFloat32Array()
## Per wall: 1 while it is switched off (a pachinko gate that is open). An off wall is left
## out of the grid, so the narrow phase never sees it and the hot loop stays unchanged.
var wall_off := PackedByteArray()

var has_ring := false
var ring_center := Vector2.ZERO
var ring_radius := 0.0
## Material: the least horizontal speed (px/s) a ball keeps after touching the ring (as a
## pin's min_speed_x; the Flash chapter resolves a ring hit as it does a pin's).
var ring_min_speed_x := 0.0

## The drain arc: a stretch of the ring (degrees) that removes a ball after drain_bounces
## bounces on it or drain_slide_time seconds of rolling on it.
var has_drain_arc := false
var drain_from := 0.0
var drain_to := 0.0
var drain_bounces := 1
var drain_slide_time := 0.5

var hole_pos := PackedVector2Array()
var hole_radius := PackedFloat32Array()
var goal_pos := PackedVector2Array()
var goal_radius := PackedFloat32Array()
var zone_pos := PackedVector2Array()
var zone_radius := PackedFloat32Array()
## True when a shape changed since the grid was built (the world rebuilds it lazily).
var dirty := true


## True when the direction `d` from the ring centre lies in the drain arc (degrees, y down,
## from drain_from clockwise on screen to drain_to).
func in_drain_arc(d: Vector2) -> bool:
	var span: float = fposmod(drain_to - drain_from, 360.0)
	if span == 0.0 and drain_to != drain_from:
		span = 360.0
	return fposmod(rad_to_deg(atan2(d.y, d.x)) - drain_from, 360.0) <= span


## True when ball slot `i`, touching the ring in direction `d` from its centre for `h` s
## (a substep), has drained: in the drain arc a bounce (`bounced`) counts toward
## drain_bounces and the time toward drain_slide_time, in `hits` and `time` (the store's
## drain_hits and drain_time).
func drained(
	d: Vector2, bounced: bool, i: int, h: float, hits: PackedInt32Array, time: PackedFloat32Array
) -> bool:
	if not has_drain_arc or not in_drain_arc(d):
		return false
	if bounced:
		hits[i] += 1
	time[i] += h
	return hits[i] >= drain_bounces or time[i] >= drain_slide_time


## Sets the ring border (BallWorld.set_ring); refuses a non-finite centre, radius <= 0 or a
## negative or non-finite min_speed_x.
func set_ring(center: Vector2, radius: float, min_speed_x: float) -> void:
	if not center.is_finite() or not is_finite(radius) or radius <= 0.0:
		var problem: String = "BallWorld.set_ring: needs a finite centre and radius > 0 (got %s, %s)"
		push_error(problem % [center, radius])
		return
	if not is_finite(min_speed_x) or min_speed_x < 0.0:
		push_error("BallWorld.set_ring: min_speed_x must be finite and >= 0 (got %s)" % min_speed_x)
		return
	has_ring = true
	ring_center = center
	ring_radius = radius
	ring_min_speed_x = min_speed_x
	dirty = true


## Makes a ring arc drain (BallWorld.set_drain_arc); refuses bad input with an error.
func set_drain_arc(from_deg: float, to_deg: float, bounces: int, slide_time: float) -> void:
	var finite: bool = is_finite(from_deg) and is_finite(to_deg) and is_finite(slide_time)
	if not finite or bounces < 1 or slide_time < 0.0:
		var problem: String = "BallWorld.set_drain_arc: needs finite angles, bounces >= 1 and"
		problem += " slide_time >= 0 (got %s, %s, %d, %s)"
		push_error(problem % [from_deg, to_deg, bounces, slide_time])
		return
	has_drain_arc = true
	drain_from = from_deg
	drain_to = to_deg
	drain_bounces = bounces
	drain_slide_time = slide_time


## Adds a pin; returns its index, or -1 with an error naming the bad input.
func add_pin(pos: Vector2, radius: float, tag: int, captures: bool, min_speed_x: float) -> int:
	if not pos.is_finite() or not is_finite(radius) or radius < 0.0:
		var problem: String = "BallWorld.add_pin: needs a finite position and radius >= 0 (got %s, %s)"
		push_error(problem % [pos, radius])
		return -1
	if not is_finite(min_speed_x) or min_speed_x < 0.0:
		var problem: String = "BallWorld.add_pin: min_speed_x must be finite and >= 0 (got %s)"
		push_error(problem % min_speed_x)
		return -1
	pin_pos.append(pos)
	pin_radius.append(radius)
	pin_tag.append(tag)
	pin_captures.append(1 if captures else 0)
	pin_min_speed_x.append(min_speed_x)
	dirty = true
	return pin_pos.size() - 1


## Adds a capsule wall; returns its index, or -1 with an error naming the bad input.
func add_wall(a: Vector2, b: Vector2, radius: float) -> int:
	if not a.is_finite() or not b.is_finite() or not is_finite(radius) or radius < 0.0:
		var problem: String = "BallWorld.add_wall: needs finite ends and radius >= 0 (got %s, %s, %s)"
		push_error(problem % [a, b, radius])
		return -1
	var ab: Vector2 = b - a
	var len2: float = ab.length_squared()
	wall_a.append(a)
	wall_b.append(b)
	wall_ab.append(ab)
	wall_inv_len2.append(1.0 / len2 if len2 > 1e-12 else 0.0)
	wall_radius.append(radius)
	wall_off.append(0)
	dirty = true
	return wall_a.size() - 1


## Switches wall `index` on or off (see BallWorld.set_wall_enabled); false for a bad index.
func set_wall_enabled(index: int, enabled: bool) -> bool:
	if index < 0 or index >= wall_a.size():
		push_error("BallWorld.set_wall_enabled: no wall %d (%d walls)" % [index, wall_a.size()])
		return false
	var off := 0 if enabled else 1
	if wall_off[index] != off:
		wall_off[index] = off
		dirty = true
	return true


## Adds a sensor circle of `kind` (SENSOR_HOLE, SENSOR_GOAL, SENSOR_ZONE); returns its index
## among its kind, or -1 with an error. Goals and zones are tracked in one bit mask per
## ball, so there are at most MAX_SENSORS of each.
func add_sensor(kind: int, center: Vector2, radius: float) -> int:
	var what: String = ["add_hole", "add_goal", "add_zone"][kind]
	if not center.is_finite() or not is_finite(radius) or radius <= 0.0:
		var problem: String = "BallWorld.%s: needs a finite centre and radius > 0 (got %s, %s)"
		push_error(problem % [what, center, radius])
		return -1
	var centres: Array[PackedVector2Array] = [hole_pos, goal_pos, zone_pos]
	if kind != SENSOR_HOLE and centres[kind].size() >= MAX_SENSORS:
		push_error("BallWorld.%s: at most %d per world" % [what, MAX_SENSORS])
		return -1
	match kind:
		SENSOR_HOLE:
			hole_pos.append(center)
			hole_radius.append(radius)
			return hole_pos.size() - 1
		SENSOR_GOAL:
			goal_pos.append(center)
			goal_radius.append(radius)
			return goal_pos.size() - 1
	zone_pos.append(center)
	zone_radius.append(radius)
	return zone_pos.size() - 1
