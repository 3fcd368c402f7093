extends RefCounted
## A BallWorld's shapes, as its callers build them: `world.shapes.add_pin(...)` and the
## other calls that add pins, capsule walls, the ring, its drain arc and sensor circles (all
## checked by StaticGeometry) and the windmills (Windmills). The world owns the geometry
## and the wheels; this is the door to them, so BallWorld's own calls are about balls and
## the step. Made by BallWorld only.

const StaticGeometry := preload("res://scripts/physics/static_geometry.gd")
const Windmills := preload("res://scripts/physics/windmills.gd")

## The world's constants (BallWorld keeps this its own): blade tips never outrun their
## max_speed (see add_windmill).
var tuning: PhysicsTuning

var _geo: StaticGeometry
var _wheels: Windmills


func _init(geo: StaticGeometry, wheels: Windmills, world_tuning: PhysicsTuning) -> void:
	_geo = geo
	_wheels = wheels
	tuning = world_tuning


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


## Adds a windmill (風車): `blades` capsule blades of `length` px (pin to the middle of the
## tip cap) and radius `blade_radius`, turning about `center`. `speed` is in rad/s, positive
## clockwise on screen: a driven wheel (`free` false) keeps it; a free wheel starts at it,
## is spun by the balls that strike it and slowed by `friction` rad/s². Blade tips never
## move faster than tuning.max_speed (a faster speed is held to it). `min_speed_x` is the
## blades' material, as a pin's (add_pin): the least horizontal speed a ball keeps after
## touching one. Returns its index, or -1 with an error on bad input.
func add_windmill(
	center: Vector2,
	blades: int,
	length: float,
	blade_radius: float,
	speed: float,
	free: bool = false,
	friction: float = 0.0,
	min_speed_x: float = 0.0
) -> int:
	var index: int = _wheels.add(
		center, blades, length, blade_radius, speed, free, friction, min_speed_x
	)
	if index >= 0:
		var cap: float = tuning.max_speed / _wheels.reach[index]
		_wheels.omega[index] = clampf(speed, -cap, cap)
		_geo.dirty = true
	return index


## How many windmills were added.
func windmill_count() -> int:
	return _wheels.count()


## The angle of windmill `index`'s first blade (radians, y down; 0 for a bad index).
func get_windmill_angle(index: int) -> float:
	return _wheels.angle[index] if index >= 0 and index < _wheels.count() else 0.0


## The angular speed of windmill `index` in rad/s, positive clockwise (0 for a bad index).
func get_windmill_speed(index: int) -> float:
	return _wheels.omega[index] if index >= 0 and index < _wheels.count() else 0.0


## Sets the ring border: balls stay inside the circle. `min_speed_x` is its material, as a
## pin's (add_pin): the least horizontal speed a ball keeps after bouncing off it (a ball
## riding the ring keeps its own, so it can stop and roll back down the launch rail).
func set_ring(center: Vector2, radius: float, min_speed_x := 0.0) -> void:
	_geo.set_ring(center, radius, min_speed_x)


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
