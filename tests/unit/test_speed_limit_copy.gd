extends GutTest
## BallMover.move_range() applies the step's rolling friction and speed cap to each moving
## ball in five written-out lines (a call per ball cost more than them): pinned here bit for
## bit to the readable rule, SpeedRules.limit(), over random tunings, gravities, frictions
## and velocities and the edge cases. The mover moves one ball on a board with no shapes, so
## the velocity it writes back is the limited one and nothing else.

const CASES := 10000
const BALL_R := 5.0

var _geo := StaticGeometry.new()
var _wheels := Windmills.new()


func before_all() -> void:
	_geo.build(BALL_R)


func _random_state(rng: RandomNumberGenerator) -> Dictionary:
	var cap: float = rng.randf_range(50.0, 1600.0)
	var speed: float = rng.randf_range(0.0, 2.0 * cap) if rng.randf() < 0.9 else rng.randf()
	var gravity := Vector2(rng.randf_range(-800, 800), rng.randf_range(-800, 800))
	if rng.randf() < 0.2:
		gravity[rng.randi_range(0, 1)] = 0.0
	var friction := Vector2(rng.randf_range(-50, 400), rng.randf_range(-50, 400))
	return {
		"per_axis": rng.randf() < 0.5,
		"against_gravity": rng.randf() < 0.5,
		"x_time": rng.randf_range(0.0, 0.05) if rng.randf() < 0.5 else 0.0,
		"cap": cap,
		"rest": rng.randf_range(0.0, 20.0),
		"gravity": gravity,
		"friction": friction,
		"dt": [1.0 / 120.0, 1.0 / 60.0][rng.randi_range(0, 1)],
		"v": Vector2.from_angle(rng.randf_range(-PI, PI)) * speed,
	}


# The edge cases: at rest, exactly at the rest speed, exactly at the cap (total and per
# axis, straight and diagonal), exactly the step's friction, no gravity, gravity on one axis,
# a negative friction (held at zero), each with both caps and both friction kinds.
func _edge_states() -> Array[Dictionary]:
	var out: Array[Dictionary] = []
	var cap := 1600.0
	var rest := 8.0
	var dt := 1.0 / 120.0
	var friction := Vector2(240.0, 240.0)
	var step_friction: Vector2 = friction * dt
	for v: Vector2 in [
		Vector2.ZERO,
		Vector2(rest, 0.0),
		Vector2(0.0, -rest),
		Vector2(cap, 0.0),
		Vector2(-cap, cap),
		Vector2(0.6, 0.8) * cap,
		Vector2(0.6, 0.8) * (cap + 1e-3),
		step_friction,
		-step_friction,
		Vector2(1e-9, -1e-9),
	]:
		for gravity: Vector2 in [Vector2.ZERO, Vector2(0.0, 777.78), Vector2(-300.0, 200.0)]:
			for mode: int in 4:
				for fr: Vector2 in [friction, Vector2(-5.0, 0.0)]:
					(
						out
						. append(
							{
								"per_axis": mode & 1 != 0,
								"against_gravity": mode & 2 != 0,
								"x_time": 0.02 if mode & 1 != 0 else 0.0,
								"cap": cap,
								"rest": rest,
								"gravity": gravity,
								"friction": fr,
								"dt": dt,
								"v": v,
							}
						)
					)
	return out


func _tuning(state: Dictionary) -> PhysicsTuning:
	var t := PhysicsTuning.new()
	t.max_speed = state["cap"]
	t.rest_speed = state["rest"]
	var per_axis: bool = state["per_axis"]
	t.speed_cap = PhysicsTuning.SpeedCap.PER_AXIS if per_axis else PhysicsTuning.SpeedCap.TOTAL
	var against_gravity: bool = state["against_gravity"]
	t.friction_against = (
		PhysicsTuning.FrictionAgainst.GRAVITY
		if against_gravity
		else PhysicsTuning.FrictionAgainst.VELOCITY
	)
	t.x_cap_friction_time = state["x_time"]
	return t


# The copy: the mover moves the one ball and writes its velocity back.
func _written_out(state: Dictionary) -> Vector2:
	var b := BallStore.new()
	b.add(Vector2.ZERO, state["v"], BALL_R)
	var m := BallMover.new()
	var hits := PackedByteArray([1, 1, 1, 1])
	var t := _tuning(state)
	m.begin(b, _geo, _wheels, t, state["gravity"], state["friction"], state["dt"], false, hits)
	m.move_range(0, 1)
	return m._vel[0]


# The readable rule, prepared as begin() prepares it.
func _readable(state: Dictionary) -> Vector2:
	var rules := SpeedRules.new()
	var friction: Vector2 = state["friction"]
	var dt: float = state["dt"]
	rules.prepare(_tuning(state), state["gravity"], friction.max(Vector2.ZERO) * dt, dt)
	return rules.limit(state["v"])


func _assert_same(state: Dictionary, what: String) -> bool:
	var a: Vector2 = _written_out(state)
	var b: Vector2 = _readable(state)
	# Bit for bit: == on floats, and a NaN (which equals nothing) would fail.
	var same: bool = a == b
	if not same:
		assert_true(same, "%s: written out %s, readable %s: %s" % [what, a, b, state])
	return same


func test_the_written_out_speed_limit_is_speed_rules_limit_bit_for_bit() -> void:
	var rng := RandomNumberGenerator.new()
	rng.seed = 43
	var failed := 0
	for k in CASES:
		if not _assert_same(_random_state(rng), "case %d" % k):
			failed += 1
			if failed > 5:
				break
	assert_eq(failed, 0, "random velocities")


func test_the_edge_cases_match_too() -> void:
	var failed := 0
	var states := _edge_states()
	for k in states.size():
		if not _assert_same(states[k], "edge %d" % k):
			failed += 1
	assert_eq(failed, 0, "edge cases")
	assert_gt(states.size(), 200)
