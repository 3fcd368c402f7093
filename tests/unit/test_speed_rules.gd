extends GutTest
## SpeedRules: the step's friction and speed cap, prepared once per step and applied to each
## moving ball in one pass. The one-pass form must give exactly what the rules say, rule by
## rule, for every option the tuning has (the tilt maze's replays and state hashes rest on
## it), and the rules themselves must do what a player sees.


## The rules as PhysicsTuning states them, one after the other.
func _by_the_rules(
	t: PhysicsTuning, v: Vector2, gravity: Vector2, friction_dt: Vector2, dt: float
) -> Vector2:
	if t.friction_against == PhysicsTuning.FrictionAgainst.GRAVITY:
		var pull: Vector2 = gravity * dt
		v.x = _against_pull(v.x, pull.x, friction_dt.x)
		v.y = _against_pull(v.y, pull.y, friction_dt.y)
	else:
		v -= v.clamp(-friction_dt, friction_dt)
	var cap: float = t.max_speed
	if t.speed_cap == PhysicsTuning.SpeedCap.PER_AXIS:
		v = v.clamp(Vector2(-cap, -cap), Vector2(cap, cap))
		var loss: float = friction_dt.x / dt * t.x_cap_friction_time if dt > 0.0 else 0.0
		var downhill: bool = gravity.x != 0.0 and signf(v.x) == signf(gravity.x)
		if t.x_cap_friction_time > 0.0 and dt > 0.0 and downhill:
			var top: float = maxf(cap - loss, 0.0)
			v.x = clampf(v.x, -top, top)
	elif v.length_squared() > cap * cap:
		v *= cap / sqrt(v.length_squared())
	return v


func _against_pull(v: float, pull: float, friction: float) -> float:
	if pull == 0.0:
		return v - clampf(v, -friction, friction)
	return v - signf(pull) * minf(friction, absf(pull))


func test_one_pass_gives_exactly_the_rules_for_every_option() -> void:
	var rng := RandomNumberGenerator.new()
	rng.seed = 21
	var rules := SpeedRules.new()
	var mismatches: Array[String] = []
	for case: int in 3000:
		var t := PhysicsTuning.new()
		t.friction_against = rng.randi_range(0, 1) as PhysicsTuning.FrictionAgainst
		t.speed_cap = rng.randi_range(0, 1) as PhysicsTuning.SpeedCap
		t.x_cap_friction_time = [0.0, 0.016, 0.05][rng.randi_range(0, 2)]
		t.max_speed = rng.randf_range(50.0, 400.0)
		var dt: float = [1.0 / 120.0, 1.0 / 60.0, 1.0 / 240.0][rng.randi_range(0, 2)]
		# Axes with no pull and with friction off happen on real boards: keep them in.
		var gravity := Vector2(_some(rng, 900.0), _some(rng, 900.0))
		var friction_dt := Vector2(absf(_some(rng, 3.0)), absf(_some(rng, 3.0)))
		rules.prepare(t, gravity, friction_dt, dt)
		for _k: int in 5:
			var v := Vector2(_some(rng, 600.0), _some(rng, 600.0))
			var got: Vector2 = rules.limit(v)
			var want: Vector2 = _by_the_rules(t, v, gravity, friction_dt, dt)
			if got != want and mismatches.size() < 5:
				mismatches.append("case %d: v %s gave %s, the rules %s" % [case, v, got, want])
	assert_eq(mismatches, [] as Array[String], "bit for bit the same as the rules")


func test_a_gentle_tilt_under_friction_against_gravity_holds_a_ball_still() -> void:
	var t := TuningPresets.maze()
	var rules := SpeedRules.new()
	var dt := 1.0 / 120.0
	var gravity := Vector2(20.0, 0.0)
	var friction_dt := Vector2(5.0, 5.0)  # more friction than the pull gives in a step
	rules.prepare(t, gravity, friction_dt, dt)
	var v: Vector2 = rules.limit(gravity * dt)
	assert_eq(v, Vector2.ZERO, "the pull is used up by friction: the ball does not start")


func test_the_total_cap_keeps_direction_and_the_per_axis_cap_each_axis() -> void:
	var t := PhysicsTuning.new()
	t.max_speed = 100.0
	var rules := SpeedRules.new()
	rules.prepare(t, Vector2.ZERO, Vector2.ZERO, 1.0 / 120.0)
	var v: Vector2 = rules.limit(Vector2(300.0, 400.0))
	assert_almost_eq(v.length(), 100.0, 1e-3)
	assert_almost_eq(v.angle(), Vector2(3.0, 4.0).angle(), 1e-5)
	t.speed_cap = PhysicsTuning.SpeedCap.PER_AXIS
	rules.prepare(t, Vector2.ZERO, Vector2.ZERO, 1.0 / 120.0)
	assert_eq(rules.limit(Vector2(300.0, -400.0)), Vector2(100.0, -100.0))


## A value in -scale .. scale, or exactly 0 one time in four.
func _some(rng: RandomNumberGenerator, scale: float) -> float:
	return 0.0 if rng.randi_range(0, 3) == 0 else rng.randf_range(-scale, scale)


## A per-axis tuning that tops x out below the cap downhill (the tilt maze seed's).
func _seed_tuning(cap: float, x_time: float) -> PhysicsTuning:
	var t := PhysicsTuning.new()
	t.max_speed = cap
	t.speed_cap = PhysicsTuning.SpeedCap.PER_AXIS
	t.x_cap_friction_time = x_time
	return t


func test_downhill_x_tops_out_below_the_cap_and_uphill_does_not() -> void:
	var rules := SpeedRules.new()
	var dt := 0.01
	# friction 0.5 px/s a step over 0.01 s for 0.4 s: x tops out 20 px/s under the cap of 100
	rules.prepare(_seed_tuning(100.0, 0.4), Vector2(50.0, 0.0), Vector2(0.5, 0.0), dt)
	assert_eq(rules.limit(Vector2(500.0, 0.0)).x, 80.0, "downhill (+x): 80")
	assert_eq(rules.limit(Vector2(-500.0, 0.0)).x, -100.0, "uphill: the plain cap")
	rules.prepare(_seed_tuning(100.0, 0.4), Vector2(-50.0, 0.0), Vector2(0.5, 0.0), dt)
	assert_eq(rules.limit(Vector2(-500.0, 0.0)).x, -80.0, "downhill (-x): -80")
	assert_eq(rules.limit(Vector2(500.0, 0.0)).x, 100.0)
	rules.prepare(_seed_tuning(100.0, 0.4), Vector2(0.05, 0.0), Vector2(0.5, 0.0), dt)
	assert_eq(rules.limit(Vector2(500.0, 0.0)).x, 80.0, "the faintest tilt right is downhill")
	rules.prepare(_seed_tuning(100.0, 0.4), Vector2(-0.05, 0.0), Vector2(0.5, 0.0), dt)
	assert_eq(rules.limit(Vector2(-500.0, 0.0)).x, -80.0, "and the faintest tilt left")


func test_friction_that_eats_the_whole_cap_holds_x_still_downhill() -> void:
	var rules := SpeedRules.new()
	rules.prepare(_seed_tuning(10.0, 1.0), Vector2(900.0, 0.0), Vector2(1.0, 0.0), 0.01)
	assert_eq(rules.limit(Vector2(40.0, 0.0)).x, 0.0, "never below zero: held, not pushed back")


func test_a_step_of_no_time_caps_as_usual() -> void:
	var rules := SpeedRules.new()
	rules.prepare(_seed_tuning(100.0, 0.4), Vector2(50.0, 0.0), Vector2(0.5, 0.0), 0.0)
	assert_eq(rules.limit(Vector2(500.0, 0.0)).x, 100.0, "no friction time, no lower top")


func test_without_a_pull_friction_slows_each_axis_toward_zero() -> void:
	var t := TuningPresets.maze()
	var rules := SpeedRules.new()
	rules.prepare(t, Vector2.ZERO, Vector2(2.0, 3.0), 0.01)
	assert_eq(rules.limit(Vector2(10.0, -10.0)), Vector2(8.0, -7.0))
	assert_eq(rules.limit(Vector2(1.0, -2.0)), Vector2.ZERO, "never past zero")
