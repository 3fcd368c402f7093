extends RefCounted
## The static half of BallWorld's façade: the calls that add pins, capsule walls, the ring,
## its drain arc and sensor circles, all checked by StaticGeometry. BallWorld extends this
## with the balls and the step. Internal to scripts/physics: use BallWorld.

const StaticGeometry := preload("res://scripts/physics/static_geometry.gd")

var _geo := StaticGeometry.new()


## Adds a pin (a fixed circle). `tag` is the owner's number for it (-1: none); a pin that
## `captures` removes a ball that touches it and reports ball_captured(ball, tag).
## `min_speed_x` is the pin's material: after touching it, a ball keeps at least this
## horizontal speed in px/s (the Flash chapter's 0.5 px/tick, so no ball balances on a pin
## top); 0 leaves the ball alone. Returns the pin index, or -1 with an error on bad input.
func add_pin(pos: Vector2, radius: float, tag := -1, captures := false, min_speed_x := 0.0) -> int:
	return _geo.add_pin(pos, radius, tag, captures, min_speed_x)


## Adds a capsule wall: the segment a-b grown by `radius`, with round caps. Returns its
## index, or -1 on bad input. A zero-length wall is a round post.
func add_wall(a: Vector2, b: Vector2, radius: float) -> int:
	return _geo.add_wall(a, b, radius)


## Switches wall `index` on or off (a gate that opens and closes). The grid is rebuilt on
## the next step, which also wakes every sleeper, so a ball resting on a gate falls.
func set_wall_enabled(index: int, enabled: bool) -> void:
	_geo.set_wall_enabled(index, enabled)


## False while wall `index` is switched off (see set_wall_enabled).
func is_wall_enabled(index: int) -> bool:
	return index >= 0 and index < _geo.wall_a.size() and _geo.wall_off[index] == 0


## Sets the ring border: balls stay inside the circle.
func set_ring(center: Vector2, radius: float) -> void:
	_geo.set_ring(center, radius)


## Makes the ring arc from `from_deg` to `to_deg` (degrees, 0 = right, 90 = down) drain:
## a ball there is removed (ball_drained) after `bounces` bounces on it, or after rolling on
## it for `slide_time` seconds.
func set_drain_arc(from_deg: float, to_deg: float, bounces: int, slide_time: float) -> void:
	_geo.set_drain_arc(from_deg, to_deg, bounces, slide_time)


## Adds a hole: a ball whose centre comes within `radius` falls in. Returns its index.
func add_hole(center: Vector2, radius: float) -> int:
	return _geo.add_sensor(StaticGeometry.SENSOR_HOLE, center, radius)


## Adds a goal: entering and leaving it are reported, the ball stays. Returns its index.
func add_goal(center: Vector2, radius: float) -> int:
	return _geo.add_sensor(StaticGeometry.SENSOR_GOAL, center, radius)


## Adds a generic sensor zone: entering it is reported. Returns its index.
func add_zone(center: Vector2, radius: float) -> int:
	return _geo.add_sensor(StaticGeometry.SENSOR_ZONE, center, radius)


## How many pins were added.
func pin_count() -> int:
	return _geo.pin_pos.size()


## How many walls were added (switched-off ones included).
func wall_count() -> int:
	return _geo.wall_a.size()
