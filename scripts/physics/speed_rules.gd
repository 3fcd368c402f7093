extends RefCounted
## Rolling friction and the speed cap of one step, for every moving ball. prepare() turns
## the tuning, this step's gravity and friction into a few numbers once per step; limit()
## then applies them to one velocity with no further calls, as it runs once per moving
## ball (a GDScript call costs about as much as the arithmetic here).
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
## which is what makes limit() one pass. Internal to scripts/physics.

## Subtracted from every velocity: the friction of the axes gravity pulls along.
var _shift := Vector2.ZERO
## Per axis, the most the velocity slows toward zero (0 on an axis with a shift).
var _toward_zero := Vector2.ZERO
var _cap := 0.0
var _per_axis := false
## True when x tops out below the cap downhill (the seed's x friction after its cap).
var _x_limited := false
var _x_pull_sign := 0.0
var _x_top := 0.0


## Takes this step's rules: `t`'s options, `gravity` (px/s²) and `friction_dt` (per axis,
## px/s this step, not negative) over `dt` s.
func prepare(t: PhysicsTuning, gravity: Vector2, friction_dt: Vector2, dt: float) -> void:
	_cap = t.max_speed
	_per_axis = t.speed_cap == PhysicsTuning.SpeedCap.PER_AXIS
	_shift = Vector2.ZERO
	_toward_zero = friction_dt
	if t.friction_against == PhysicsTuning.FrictionAgainst.GRAVITY:
		var pull: Vector2 = gravity * dt
		if pull.x != 0.0:
			_shift.x = signf(pull.x) * minf(friction_dt.x, absf(pull.x))
			_toward_zero.x = 0.0
		if pull.y != 0.0:
			_shift.y = signf(pull.y) * minf(friction_dt.y, absf(pull.y))
			_toward_zero.y = 0.0
	var x_time: float = t.x_cap_friction_time if _per_axis else 0.0
	_x_limited = x_time > 0.0 and dt > 0.0 and gravity.x != 0.0
	_x_pull_sign = signf(gravity.x)
	_x_top = maxf(_cap - friction_dt.x / dt * x_time, 0.0) if _x_limited else _cap


## Velocity `v` (this step's gravity already added) after the step's friction and cap.
func limit(v: Vector2) -> Vector2:
	v -= _shift
	v -= v.clamp(-_toward_zero, _toward_zero)
	if _per_axis:
		v = v.clamp(Vector2(-_cap, -_cap), Vector2(_cap, _cap))
	else:
		var speed2: float = v.length_squared()
		if speed2 > _cap * _cap:
			v *= _cap / sqrt(speed2)
	if _x_limited and signf(v.x) == _x_pull_sign:
		v.x = clampf(v.x, -_x_top, _x_top)
	return v
