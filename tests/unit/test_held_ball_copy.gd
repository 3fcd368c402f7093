extends GutTest
## BallSolve.solve_pairs() answers a pair with one ball held from behind (asleep, or
## pressed last step on a static shape or a held ball facing the other) in one written-out
## branch (a pile has hundreds of these pairs a step): pinned here bit for bit to the
## readable rule, BallSolve.off_held(), over random pairs, each way of being held, either
## ball held, and the edge cases. The held ball keeps its velocity; the free one takes
## off_held()'s.

## The ways a ball is held from behind (see solve_pairs()).
enum Held { ASLEEP, STATIC, STATIC2, BALL }

const CASES := 10000


## A solve of one pair, ball `held` (0 or 1) held from behind the way `how` says.
func _solve(state: Dictionary) -> BallSolve:
	var b := BallStore.new()
	b.add(state["p0"], state["v0"], state["r0"])
	b.add(state["p1"], state["v1"], state["r1"])
	var held: int = state["held"]
	var free: int = 1 - held
	var toward_free: Vector2 = _normal(state) * (1.0 if held == 0 else -1.0)
	# A support is the normal of what a ball pressed on, pointing to the ball: a shape
	# behind the held ball points toward the free one.
	var behind: Vector2 = toward_free.rotated(state["tilt"])
	match state["how"]:
		Held.ASLEEP:
			b.asleep[held] = 1
		Held.STATIC:
			b.support_static[held] = behind
		Held.STATIC2:
			b.support_static2[held] = behind
		_:
			b.support_ball[held] = behind
	# The free ball pressed on something on the held ball's side: no hold against it.
	b.support_static[free] = behind
	var solve := BallSolve.new()
	solve.begin(b, state["e"], state["threshold"], state["wake"], state["gravity_dt"])
	solve.solve_pairs(PackedInt32Array([0, 1]), 2)
	return solve


# The line from ball 0 to ball 1 as solve_pairs() finds it.
func _normal(state: Dictionary) -> Vector2:
	var d: Vector2 = state["p1"] - state["p0"]
	var dist: float = sqrt(d.length_squared())
	return d / dist if dist > BallSolve.EPS else Vector2(1.0, 0.0)


func _random_state(rng: RandomNumberGenerator) -> Dictionary:
	var r0 := rng.randf_range(3.0, 10.0)
	var r1 := rng.randf_range(3.0, 10.0)
	var p0 := Vector2(rng.randf_range(-100, 100), rng.randf_range(-100, 100))
	var gap: float = (r0 + r1) * rng.randf_range(0.0, 1.0)
	var p1: Vector2 = p0 + Vector2.from_angle(rng.randf_range(-PI, PI)) * gap
	var s0 := rng.randf_range(0.0, 1600.0) if rng.randf() < 0.9 else rng.randf_range(0, 2)
	var s1 := rng.randf_range(0.0, 1600.0) if rng.randf() < 0.9 else rng.randf_range(0, 2)
	var how: int = rng.randi_range(0, 3)
	return {
		"p0": p0,
		"p1": p1,
		"r0": r0,
		"r1": r1,
		"v0": Vector2.from_angle(rng.randf_range(-PI, PI)) * s0,
		"v1": Vector2.from_angle(rng.randf_range(-PI, PI)) * s1,
		"held": rng.randi_range(0, 1),
		"how": how,
		# Within 60° of straight behind: it holds (SUPPORT_COS is cos 60°).
		"tilt": rng.randf_range(-1.0, 1.0),
		"e": rng.randf_range(0.0, 1.0),
		"threshold": rng.randf_range(0.0, 60.0),
		# A sleeper that a fast ball woke would be free: here it stays asleep.
		"wake": 1e30 if how == Held.ASLEEP else rng.randf_range(0.0, 100.0),
		"gravity_dt": Vector2(rng.randf_range(-3, 3), rng.randf_range(-2, 9)),
	}


# The edge cases, each way of being held and either ball held: at rest, moving off
# (leaving), sliding across (no normal speed), straight in, exactly at the bounce threshold
# (with and without gravity's approach), a hair faster, grazing (a hair of normal speed),
# and two balls with the same centre.
func _edge_states() -> Array[Dictionary]:
	var out: Array[Dictionary] = []
	var threshold := 30.0
	var gravity_dt := Vector2(0.0, 6.48)
	for held: int in 2:
		var into: Vector2 = Vector2(0.6, -0.8) if held == 1 else Vector2(-0.6, 0.8)
		var across := Vector2(0.8, 0.6)
		var gn: float = minf(gravity_dt.dot(-into), 0.0)
		for v: Vector2 in [
			Vector2.ZERO,
			-into * 200.0,
			across * 200.0,
			into * 200.0,
			into * (threshold + gn),
			into * threshold,
			into * (threshold + gn + 1e-3),
			across * 200.0 + into * 1e-6,
		]:
			for how: int in 4:
				for same_centre: bool in [false, true]:
					var p1: Vector2 = Vector2(3.0, -4.0) * (0.0 if same_centre else 1.5)
					(
						out
						. append(
							{
								"p0": Vector2.ZERO,
								"p1": p1,
								"r0": 5.0,
								"r1": 5.0,
								"v0": v if held == 1 else Vector2(10, 0),
								"v1": v if held == 0 else Vector2(10, 0),
								"held": held,
								"how": how,
								"tilt": 0.0,
								"e": 0.6,
								"threshold": threshold,
								"wake": 1e30,
								"gravity_dt": gravity_dt,
							}
						)
					)
	return out


func _assert_same(state: Dictionary, what: String) -> bool:
	var solve := _solve(state)
	var held: int = state["held"]
	var free: int = 1 - held
	var away: Vector2 = _normal(state) * (1.0 if held == 0 else -1.0)
	var v: Vector2 = state["v1"] if free == 1 else state["v0"]
	var want: Vector2 = BallSolve.off_held(
		v, away, state["gravity_dt"], state["e"], state["threshold"]
	)
	var held_v: Vector2 = state["v1"] if held == 1 else state["v0"]
	var same: bool = solve._vel[free] == want and solve._vel[held] == held_v
	if not same:
		var got := (
			"written out %s (held %s), readable %s" % [solve._vel[free], solve._vel[held], want]
		)
		assert_true(same, "%s: %s: %s" % [what, got, state])
	return same


func test_the_written_out_held_ball_branch_is_off_held_bit_for_bit() -> void:
	var rng := RandomNumberGenerator.new()
	rng.seed = 433
	var failed := 0
	var changed := 0
	for k in CASES:
		var state := _random_state(rng)
		var solve := _solve(state)
		if solve._vel[1 - int(state["held"])] != state["v1" if state["held"] == 0 else "v0"]:
			changed += 1
		if not _assert_same(state, "case %d" % k):
			failed += 1
			if failed > 5:
				break
	assert_eq(failed, 0, "random pairs")
	# About half the pairs approach: those are the answers pinned.
	assert_gt(changed, CASES / 3, "pairs answered")


func test_the_edge_cases_match_too() -> void:
	var failed := 0
	var states := _edge_states()
	for k in states.size():
		if not _assert_same(states[k], "edge %d" % k):
			failed += 1
	assert_eq(failed, 0, "edge cases")
	assert_eq(states.size(), 128)
