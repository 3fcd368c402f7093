# gdlint: disable=max-public-methods
# The door to the shapes is one contract (scripts/physics/README.md); its calls are small
# on purpose.
class_name WorldShapes
extends RefCounted
## A BallWorld's shapes, as its callers build them: `world.shapes.add_pin(...)` and the
## other calls that add pins, capsule walls, the ring, its drain arc and sensor circles (all
## checked by StaticShapes), the windmills (Windmills) and the gates (Gates, whose
## petals are rotors of the same store). The world owns the geometry, the wheels and the
## gates; this is the door to them, so BallWorld's own calls are about balls and the step.
## Made by BallWorld only.

## The world's constants (BallWorld keeps this its own): blade tips never outrun their
## max_speed (see add_windmill).
var tuning: PhysicsTuning

## The grid (bin) and the static shapes it bins (the adds go to them).
var _geo: StaticGeometry
var _shapes: StaticShapes
var _wheels: Windmills
var _gates: Gates
## Windmill index → its rotor in _wheels; per rotor, its windmill or gate index and 1 when
## it is a gate's petal (the hit events name windmills and gates, not rotors).
var _windmill_rotor := PackedInt32Array()
var _rotor_owner := PackedInt32Array()
var _rotor_is_petal := PackedByteArray()


func _init(
	geo: StaticGeometry, wheels: Windmills, gates: Gates, world_tuning: PhysicsTuning
) -> void:
	_geo = geo
	_shapes = geo.shapes
	_wheels = wheels
	_gates = gates
	tuning = world_tuning


## Bins the static shapes and the windmills into the grid for balls up to `ball_radius`
## (every pin in one list without `zoning`; see StaticGeometry.build).
func bin(ball_radius: float, zoning: bool) -> void:
	_geo.kinematic_points = _wheels.bounds_points()
	_geo.build(ball_radius, zoning)
	if _wheels.count() > 0:
		_geo.min_feature = minf(_geo.min_feature, _wheels.min_blade_radius)
		# A ball moving at the top speed stays within this of where it started a step.
		var travel: float = tuning.max_speed / maxf(tuning.fixed_hz, 1.0) + ball_radius
		var grow: float = ball_radius + StaticGeometry.BIN_MARGIN
		_wheels.bin(_geo.origin, _geo.cell, _geo.cols, _geo.rows, grow, travel)


## Adds a pin (a fixed circle). `tag` is the owner's number for it (-1: none); a pin that
## `captures` removes a ball that touches it and reports ball_captured(ball, tag).
## `min_speed_x` is the pin's material: after touching it, a ball keeps at least this
## horizontal speed in px/s (the Flash chapter's 0.5 px/tick, so no ball balances on a pin
## top); 0 leaves the ball alone. Returns the pin index, or -1 with an error on bad input.
func add_pin(pos: Vector2, radius: float, tag := -1, captures := false, min_speed_x := 0.0) -> int:
	return _shapes.add_pin(pos, radius, tag, captures, min_speed_x)


## Adds a capsule wall: the segment a-b grown by `radius`, with round caps. Returns its
## index, or -1 on bad input. A zero-length wall is a round post.
func add_wall(a: Vector2, b: Vector2, radius: float) -> int:
	return _shapes.add_wall(a, b, radius)


## Switches wall `index` on or off (a gate that opens and closes). The grid is rebuilt on
## the next step, which also wakes every sleeper, so a ball resting on a gate falls.
func set_wall_enabled(index: int, enabled: bool) -> void:
	_shapes.set_wall_enabled(index, enabled)


## False while wall `index` is switched off (see set_wall_enabled).
func is_wall_enabled(index: int) -> bool:
	return index >= 0 and index < _shapes.wall_a.size() and _shapes.wall_off[index] == 0


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
	if index < 0:
		return -1
	var cap: float = tuning.max_speed / _wheels.reach[index]
	_wheels.omega[index] = clampf(speed, -cap, cap)
	_shapes.dirty = true
	_windmill_rotor.append(index)
	_rotor_owner.append(_windmill_rotor.size() - 1)
	_rotor_is_petal.append(0)
	return _windmill_rotor.size() - 1


## How many windmills were added.
func windmill_count() -> int:
	return _windmill_rotor.size()


## The angle of windmill `index`'s first blade (radians, y down; 0 for a bad index).
func get_windmill_angle(index: int) -> float:
	if index < 0 or index >= _windmill_rotor.size():
		return 0.0
	return _wheels.angle[_windmill_rotor[index]]


## The angular speed of windmill `index` in rad/s, positive clockwise (0 for a bad index).
func get_windmill_speed(index: int) -> float:
	if index < 0 or index >= _windmill_rotor.size():
		return 0.0
	return _wheels.omega[_windmill_rotor[index]]


## Adds a gate, shut: a set of petals (add_petal) that swing open and shut together, each
## whole swing taking `swing_seconds` (or longer: no petal tip moves faster than
## tuning.max_speed). Open and shut it with set_gate_open, or let it run on a schedule
## (set_gate_schedule). Returns its index, or -1 with an error on bad input.
func add_gate(swing_seconds: float) -> int:
	return _gates.add(swing_seconds)


## Adds a petal to `gate`: a capsule of `length` px (hinge to the middle of its tip cap)
## and radius `radius`, hinged at `hinge`, pointing at `shut_angle` while the gate is shut
## and at `open_angle` while it is open (radians, y down, so -PI / 2 is straight up).
## `min_speed_x` is its material, as a pin's (add_pin). Balls touch it as they touch a
## windmill's blade: they see its surface speed, and none passes through it. Returns the
## petal's index, or -1 with an error on bad input.
func add_petal(
	gate: int,
	hinge: Vector2,
	length: float,
	radius: float,
	shut_angle: float,
	open_angle: float,
	min_speed_x: float = 0.0
) -> int:
	var sizes_ok: bool = is_finite(length) and is_finite(radius) and length > 0.0 and radius > 0.0
	var angles_ok: bool = is_finite(shut_angle) and is_finite(open_angle)
	var material_ok: bool = is_finite(min_speed_x) and min_speed_x >= 0.0
	var numbers_ok: bool = hinge.is_finite() and sizes_ok and angles_ok and material_ok
	if gate < 0 or gate >= _gates.count() or not numbers_ok:
		var problem := "BallWorld.add_petal: needs a gate added before, a finite hinge and angles,"
		problem += " length > 0, radius > 0 and min_speed_x >= 0"
		var got := " (got gate %d, %s, %s, %s, %s, %s, %s)"
		var values: Array = [gate, hinge, length, radius, shut_angle, open_angle, min_speed_x]
		push_error(problem + got % values)
		return -1
	var rotor: int = _wheels.add(hinge, 1, length, radius, 0.0, false, 0.0, min_speed_x)
	if rotor < 0:
		return -1
	_shapes.dirty = true
	var petal: int = _gates.add_petal(_wheels, gate, rotor, shut_angle, open_angle)
	_rotor_owner.append(gate)
	_rotor_is_petal.append(1)
	return petal


## Sends `gate` open or shut: its petals swing there over the following steps, or with
## `at_once` are there now. Unknown gates are ignored.
func set_gate_open(gate: int, open: bool, at_once: bool = false) -> void:
	if gate >= 0 and gate < _gates.count():
		_gates.set_open(_wheels, gate, open, at_once)


## Runs `gate` on its own: open for `open_seconds`, then shut for `shut_seconds`, over and
## over from the phase it is heading for now; both 0 stops the schedule (it stays as it
## is). Refuses times that are not finite and >= 0 with an error.
func set_gate_schedule(gate: int, open_seconds: float, shut_seconds: float) -> void:
	var fine: bool = is_finite(open_seconds) and is_finite(shut_seconds)
	if gate < 0 or gate >= _gates.count() or not fine or open_seconds < 0.0 or shut_seconds < 0.0:
		var problem := "BallWorld.set_gate_schedule: needs a gate and times finite and >= 0"
		push_error(problem + " (got %d, %s, %s)" % [gate, open_seconds, shut_seconds])
		return
	_gates.set_schedule(gate, open_seconds, shut_seconds)


## How many gates were added.
func gate_count() -> int:
	return _gates.count()


## How open `gate` is now: 0 shut, 1 open, between while it swings (0 for a bad index).
func get_gate_openness(gate: int) -> float:
	return _gates.openness[gate] if gate >= 0 and gate < _gates.count() else 0.0


## True while `gate` is heading open (or is open).
func is_gate_opening(gate: int) -> bool:
	return gate >= 0 and gate < _gates.count() and _gates.target[gate] != 0


## The angle petal `petal` points at now (radians, y down; 0 for a bad index).
func get_petal_angle(petal: int) -> float:
	if petal < 0 or petal >= _gates.petal_count():
		return 0.0
	return _wheels.angle[_gates.petal_rotor[petal]]


## Sets the ring border: balls stay inside the circle. `min_speed_x` is its material, as a
## pin's (add_pin): the least horizontal speed a ball keeps after bouncing off it (a ball
## riding the ring keeps its own, so it can stop and roll back down the launch rail).
func set_ring(center: Vector2, radius: float, min_speed_x := 0.0) -> void:
	_shapes.set_ring(center, radius, min_speed_x)


## Makes the ring arc from `from_deg` to `to_deg` (degrees, 0 = right, 90 = down) drain:
## a ball there is removed (ball_drained) after `bounces` bounces on it, or after rolling on
## it for `slide_time` seconds.
func set_drain_arc(from_deg: float, to_deg: float, bounces: int, slide_time: float) -> void:
	_shapes.set_drain_arc(from_deg, to_deg, bounces, slide_time)


## Adds a hole: a ball whose centre comes within `radius` falls in. Returns its index.
func add_hole(center: Vector2, radius: float) -> int:
	return _shapes.add_sensor(StaticShapes.SENSOR_HOLE, center, radius)


## Adds a goal: entering and leaving it are reported, the ball stays. Returns its index.
func add_goal(center: Vector2, radius: float) -> int:
	return _shapes.add_sensor(StaticShapes.SENSOR_GOAL, center, radius)


## Adds a generic sensor zone: entering it is reported. Returns its index.
func add_zone(center: Vector2, radius: float) -> int:
	return _shapes.add_sensor(StaticShapes.SENSOR_ZONE, center, radius)


## How many pins were added.
func pin_count() -> int:
	return _shapes.pin_pos.size()


## How many walls were added (switched-off ones included).
func wall_count() -> int:
	return _shapes.wall_a.size()


## The windmill or gate that rotor `rotor` belongs to (BallWorld names it in hit events).
func rotor_owner(rotor: int) -> int:
	return _rotor_owner[rotor]


## True when rotor `rotor` is a gate's petal rather than a windmill's.
func rotor_is_petal(rotor: int) -> bool:
	return _rotor_is_petal[rotor] != 0
