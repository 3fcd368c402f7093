class_name SpeedRules
extends RefCounted
## Rolling friction and the speed cap of one step, for every moving ball. prepare() turns
## the tuning, this step's gravity and friction into a few numbers once per step; limit()
## applies them to one velocity in a few lines with no call, and the motion stage writes
## those lines out per ball (a GDScript call costs more than the arithmetic here).
##
## The rules (see PhysicsTuning):
## - friction against the velocity: each axis slows by up to this step's friction, never
##   past zero;
## - friction against gravity (the tilt maze seed): on an axis gravity pulls along, the
##   friction comes off the pull, down to zero at most (a gentle tilt holds the ball instead
##   of rolling it uphill); an axis with no pull slows toward zero as above;
## - the cap on the total speed, or on each axis (the seed's); under the per-axis cap, x then
##   loses `x_cap_friction_time` s of friction more while gravity pulls the ball along x.
## Both friction kinds become one constant shift plus one slowing toward zero per axis,
## and both caps one clamp or one length test: that is what makes limit() one pass.
## Internal to scripts/physics.

## Subtracted from every velocity: the friction of the axes gravity pulls along.
var shift := Vector2.ZERO
## Per axis, the most the velocity slows toward zero (0 on an axis with a shift).
var toward_zero := Vector2.ZERO
## True when the cap is per axis: the velocity is clamped to low .. high. Else its length
## is capped at `cap`.
var per_axis := false
var cap := 0.0
## The per-axis cap as a box. The seed's x friction after its cap (x tops out below the cap
## downhill only) makes it lopsided: with gravity pulling to +x, high.x is the lower top.
var low := Vector2.ZERO
var high := Vector2.ZERO


## Takes this step's rules: `t`'s options, `gravity` (px/s²) and `friction_dt` (per axis,
## px/s this step, not negative) over `dt` s.
func prepare(t: PhysicsTuning, gravity: Vector2, friction_dt: Vector2, dt: float) -> void:
	cap = t.max_speed
	per_axis = t.speed_cap == PhysicsTuning.SpeedCap.PER_AXIS
	shift = Vector2.ZERO
	toward_zero = friction_dt
	if t.friction_against == PhysicsTuning.FrictionAgainst.GRAVITY:
		var pull: Vector2 = gravity * dt
		if pull.x != 0.0:
			shift.x = signf(pull.x) * minf(friction_dt.x, absf(pull.x))
			toward_zero.x = 0.0
		if pull.y != 0.0:
			shift.y = signf(pull.y) * minf(friction_dt.y, absf(pull.y))
			toward_zero.y = 0.0
	low = Vector2(-cap, -cap)
	high = Vector2(cap, cap)
	var x_time: float = t.x_cap_friction_time if per_axis else 0.0
	if x_time > 0.0 and dt > 0.0 and gravity.x != 0.0:
		var x_top: float = maxf(cap - friction_dt.x / dt * x_time, 0.0)
		if gravity.x > 0.0:
			high.x = x_top
		else:
			low.x = -x_top


## Velocity `v` (this step's gravity already added) after the step's friction and cap.
## (BallMover writes these lines out in its own loop, a call per ball costing more than
## them; tests/unit/test_speed_limit_copy.gd pins that copy to this bit for bit.)
func limit(v: Vector2) -> Vector2:
	v -= shift
	v -= v.clamp(-toward_zero, toward_zero)
	if per_axis:
		v = v.clamp(low, high)
	elif v.length_squared() > cap * cap:
		v *= cap / sqrt(v.length_squared())
	return v
