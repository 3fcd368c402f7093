class_name MazeTilt
extends RefCounted
## Maps a maze board's tilt to the forces on its balls, as the tilt maze seed does:
## per axis, gravity `g · sin θ` and rolling friction `μ·g · cos θ`.
## Tilt in degrees: x tilts the board left/right (balls accelerate along x), y up/down.
## A game rule, not physics: the world only sees the gravity and friction it gets.
## Near level the board is felt-lined (felt_drag): trial 10, "balls keep rolling for seconds
## after the board levels; the same double tap moved a ball 18 to 100 px". The felt fades out
## as the tilt grows, so a run at full tilt keeps its speed.

## The felt's extra rolling drag on a level board, in parts of the tuning's μ·g.
const FELT := 4.0
## The felt is whole up to this tilt (degrees, the tilt's length)...
const FELT_FULL_DEG := 0.25
## ...and gone from this one: a tap's nudge (6.6°), the fine one (4.3°) and any
## hold roll free of it; a ball at rest needs about 1.1° to start (0.6° without the felt).
const FELT_GONE_DEG := 1.5


## Sets `world`'s gravity and rolling friction for a tilt in degrees, from its tuning's
## tilt_gravity (g) and rolling_friction (μ·g).
static func apply(world: BallWorld, tilt_deg: Vector2) -> void:
	world.gravity = gravity(tilt_deg, world.tuning.tilt_gravity)
	var rolling := world.tuning.rolling_friction
	world.rolling_friction = (
		friction(tilt_deg, rolling) + Vector2.ONE * felt_drag(tilt_deg, rolling)
	)


## Gravity in px/s² for a tilt in degrees, with `tilt_gravity` the full g (px/s²).
static func gravity(tilt_deg: Vector2, tilt_gravity: float) -> Vector2:
	return Vector2(
		tilt_gravity * sin(deg_to_rad(tilt_deg.x)), tilt_gravity * sin(deg_to_rad(tilt_deg.y))
	)


## Per-axis rolling friction in px/s² for a tilt in degrees, with `rolling_friction` = μ·g.
static func friction(tilt_deg: Vector2, rolling_friction: float) -> Vector2:
	return Vector2(
		rolling_friction * cos(deg_to_rad(tilt_deg.x)),
		rolling_friction * cos(deg_to_rad(tilt_deg.y))
	)


## The felt's extra rolling drag in px/s² (both axes) for a tilt in degrees, with
## `rolling_friction` = μ·g: FELT times it on a level board, fading smoothly to nothing between
## FELT_FULL_DEG and FELT_GONE_DEG of tilt (the tilt's length, so a tilt along one axis frees
## the other too and a full-tilt run along a wall is as fast as before).
static func felt_drag(tilt_deg: Vector2, rolling_friction: float) -> float:
	var fade := smoothstep(FELT_FULL_DEG, FELT_GONE_DEG, tilt_deg.length())
	return FELT * rolling_friction * (1.0 - fade)


## Slows `speed` toward zero by `amount` (>= 0) without passing zero: friction only slows.
static func slow(speed: float, amount: float) -> float:
	if absf(speed) <= amount:
		return 0.0
	return speed - amount if speed > 0.0 else speed + amount
