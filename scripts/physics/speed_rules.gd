extends RefCounted
## Rolling friction and the speed cap for the tuning options that are not the motion
## stage's inline defaults (friction against velocity, a cap on the total speed): friction
## against gravity's downhill direction and a cap per axis, as the tilt maze seed does.
## Internal to scripts/physics.


## Velocity `v` (this step's gravity already added) after friction that opposes the
## downhill direction: per axis, `friction_dt` (px/s this step) comes off the pull
## `gravity_dt`, down to zero at most, so a gentle tilt holds the ball instead of rolling it
## uphill (the seed's joystick never reaches such a tilt). An axis with no pull slows toward
## zero and never past it.
static func friction_against_gravity(
	v: Vector2, gravity_dt: Vector2, friction_dt: Vector2
) -> Vector2:
	return Vector2(
		_axis_against_gravity(v.x, gravity_dt.x, friction_dt.x),
		_axis_against_gravity(v.y, gravity_dt.y, friction_dt.y)
	)


## Velocity `v` (this step's gravity already added) after one step of friction and the
## speed cap under the seed's options: friction against `gravity`'s pull or against the
## velocity (`friction_dt` per axis, px/s this step), the cap `cap` on the total speed or
## per axis, and `x_cap_friction_time` s of x friction after the cap (see x_after_cap).
static func seed_rules(
	v: Vector2,
	gravity: Vector2,
	friction_dt: Vector2,
	dt: float,
	cap: float,
	per_axis: bool,
	against_gravity: bool,
	x_cap_friction_time: float
) -> Vector2:
	if against_gravity:
		v = friction_against_gravity(v, gravity * dt, friction_dt)
	elif friction_dt != Vector2.ZERO:
		v -= v.clamp(-friction_dt, friction_dt)
	v = capped(v, cap, per_axis)
	if x_cap_friction_time > 0.0 and dt > 0.0:
		v.x = x_after_cap(v.x, gravity.x, cap, friction_dt.x / dt * x_cap_friction_time)
	return v


## The plain rules: friction `friction` (per axis, this step's) slows each axis by up to it
## and never past zero, then the speed is capped at `max_speed`.
static func plain(v: Vector2, friction: Vector2, max_speed: float) -> Vector2:
	var out: Vector2 = v - v.clamp(-friction, friction)
	var speed2: float = out.length_squared()
	if speed2 > max_speed * max_speed:
		out *= max_speed / sqrt(speed2)
	return out


## `v` with its total speed capped at `cap`, or each axis capped when `per_axis`.
static func capped(v: Vector2, cap: float, per_axis: bool) -> Vector2:
	if per_axis:
		return v.clamp(Vector2(-cap, -cap), Vector2(cap, cap))
	var speed2: float = v.length_squared()
	if speed2 > cap * cap:
		return v * (cap / sqrt(speed2))
	return v


## The x speed `vx` (already capped at `cap`) as the seed leaves it when it takes a frame's
## friction after the cap: while gravity pulls along x (`pull_x`), the downhill speed tops out
## at `cap - loss`; uphill and with no pull the cap stays.
static func x_after_cap(vx: float, pull_x: float, cap: float, loss: float) -> float:
	if pull_x == 0.0 or signf(vx) != signf(pull_x):
		return vx
	var top := maxf(cap - loss, 0.0)
	return clampf(vx, -top, top)


static func _axis_against_gravity(v: float, pull: float, friction: float) -> float:
	if pull == 0.0:
		return v - clampf(v, -friction, friction)
	return v - signf(pull) * minf(friction, absf(pull))
