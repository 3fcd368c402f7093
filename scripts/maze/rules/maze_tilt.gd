class_name MazeTilt
extends RefCounted
## Maps a maze board's tilt to the forces on its balls, as the tilt maze seed does:
## per axis, gravity `g · sin θ` and rolling friction `μ·g · cos θ`.
## Tilt in degrees: x tilts the board left/right (balls accelerate along x), y up/down.
## A game rule, not physics: the world only sees the gravity and friction it gets.


## Sets `world`'s gravity and rolling friction for a tilt in degrees, from its tuning's
## tilt_gravity (g) and rolling_friction (μ·g).
static func apply(world: BallWorld, tilt_deg: Vector2) -> void:
	world.gravity = gravity(tilt_deg, world.tuning.tilt_gravity)
	world.rolling_friction = friction(tilt_deg, world.tuning.rolling_friction)


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


## Slows `speed` toward zero by `amount` (>= 0) without passing zero: friction only slows.
static func slow(speed: float, amount: float) -> float:
	if absf(speed) <= amount:
		return 0.0
	return speed - amount if speed > 0.0 else speed + amount
