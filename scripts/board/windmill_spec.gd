@tool
class_name WindmillSpec
extends Resource
## One windmill (風車) of a pachinko board: a wheel of blades turning about a pin at
## `position`. A driven wheel turns at `speed` all the time; a free wheel stands still until
## balls strike it, spins with them and slows by its `friction`. The world builds it with
## BallWorld.add_windmill (BoardWorldFactory).
##
## Board files hold one per line: `{"windmill": {"id": 1, "x": 240, "y": 300, "blades": 4,
## "length": 22, "speed": 120}}` (driven) or `..., "friction": 180}}` (free); see
## board_schema.gd for the ranges. Angles in degrees, y down: a positive speed turns
## clockwise on screen.

## Blade thickness: the capsule radius of every blade (px).
const BLADE_RADIUS := 2.0
## What the editor places: a four-blade wheel turning at DEFAULT_SPEED.
const DEFAULT_BLADES := 4
const DEFAULT_LENGTH := 22.0
const DEFAULT_SPEED := 120.0
const DEFAULT_FRICTION := 180.0
## The blade counts and lengths (px) a board may use, also the file's ranges.
const BLADES_RANGE := Vector2i(2, 12)
const LENGTH_RANGE := Vector2(8.0, 120.0)
## The most a driven wheel's speed may be, and a free wheel's friction (deg/s, deg/s²).
const MAX_SPEED := 3600.0
const MAX_FRICTION := 36000.0

## The pin the wheel turns about, board pixels.
@export var position: Vector2 = Vector2.ZERO:
	set(value):
		position = value
		emit_changed()
## How many blades, evenly spaced.
@export var blades: int = DEFAULT_BLADES:
	set(value):
		blades = value
		emit_changed()
## From the pin to the middle of a blade's rounded tip (px).
@export var length: float = DEFAULT_LENGTH:
	set(value):
		length = value
		emit_changed()
## True: spun by the balls and slowed by `friction`; false: driven at `speed`.
@export var free_spin: bool = false:
	set(value):
		free_spin = value
		emit_changed()
## A driven wheel's speed, degrees a second, positive clockwise on screen.
@export var speed: float = DEFAULT_SPEED:
	set(value):
		speed = value
		emit_changed()
## A free wheel's friction: degrees a second it loses each second.
@export var friction: float = DEFAULT_FRICTION:
	set(value):
		friction = value
		emit_changed()


## A driven wheel (a convenience for code, tests and the editor).
static func driven(
	at: Vector2, blade_count: int, blade_length: float, deg_per_s: float
) -> WindmillSpec:
	var spec := WindmillSpec.new()
	spec.position = at
	spec.blades = blade_count
	spec.length = blade_length
	spec.speed = deg_per_s
	return spec


## A free-spinning wheel slowed by `deg_per_s2`.
static func spinning_free(
	at: Vector2, blade_count: int, blade_length: float, deg_per_s2: float
) -> WindmillSpec:
	var spec := WindmillSpec.new()
	spec.position = at
	spec.blades = blade_count
	spec.length = blade_length
	spec.free_spin = true
	spec.speed = 0.0
	spec.friction = deg_per_s2
	return spec


## The radius of the circle the blades sweep (tip caps included), px.
func sweep_radius() -> float:
	return length + BLADE_RADIUS


## How fast a blade tip moves (px/s): a driven wheel's, 0 for a free one at rest.
func tip_speed() -> float:
	return 0.0 if free_spin else absf(deg_to_rad(speed)) * sweep_radius()


## A copy moved by `offset` (every field kept).
func moved(offset: Vector2) -> WindmillSpec:
	var copy := duplicate() as WindmillSpec
	copy.position = position + offset
	return copy
