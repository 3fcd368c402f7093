class_name WorldInputChecks
extends RefCounted
## The world's gate for bad input from outside: a spawn or a step with non-finite numbers
## is named in an error rather than let into the arrays, where one NaN would spread to every
## ball it touches and every hash after it. BallWorld asks before it acts.


## The error for a spawn at `pos` moving `vel` with `radius`, or "" when it is fine.
static func spawn_problem(pos: Vector2, vel: Vector2, radius: float) -> String:
	if pos.is_finite() and vel.is_finite() and is_finite(radius) and radius > 0.0:
		return ""
	var problem := "BallWorld.spawn_ball: needs a finite position and velocity"
	problem += " and radius > 0 (got %s, %s, %s)"
	return problem % [pos, vel, radius]


## The error for a step of `dt` seconds, or "" when it is fine.
static func step_problem(dt: float) -> String:
	if is_finite(dt) and dt > 0.0:
		return ""
	return "BallWorld.step: dt must be finite and > 0 (got %s)" % dt


## `force` when finite; else zero, with an error naming `what` (gravity, rolling_friction).
static func finite_or_zero(force: Vector2, what: String) -> Vector2:
	if force.is_finite():
		return force
	push_error("BallWorld.step: %s must be finite (got %s); using zero" % [what, force])
	return Vector2.ZERO
