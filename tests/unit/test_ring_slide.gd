extends GutTest
## BallMover._touch_ring() answers a ball sliding on the ring with respond()'s slide
## written out (a ball riding the launch rail touches the ring about once a step): pinned
## here bit for bit to the readable path, the ball put back on the ring and answered by
## respond(), over random contacts and the edge cases.

const CASES := 10000
## Contact ids a ball may hold besides the ring's: a pin's and a wall's.
const OTHER_A := (3 << ContactId.KIND_BITS) | ContactId.KIND_PIN
const OTHER_B := (5 << ContactId.KIND_BITS) | ContactId.KIND_WALL


## A mover in the middle of a step, with the ball just past the ring (`state` sets the
## ball, its held and current contacts and the constants).
func _mover(state: Dictionary) -> BallMover:
	var m := BallMover.new()
	m._ring_center = state["center"]
	m._ring_lim = state["lim"]
	m._ring_min_speed_x = state["min_x"]
	m._has_drain_arc = false
	m._gravity = state["gravity"]
	m._dt = 1.0 / 120.0
	m._h = m._dt / state["substeps"]
	m._threshold = state["threshold"]
	m._pin_e = state["e"]
	m._wall_e = state["e"]
	m._keep_tangent = state["keep"]
	m._hits_heard = PackedByteArray([1, 1, 1, 1])
	m._ids = PackedInt32Array([7])
	m._i = 0
	m._p = state["p"]
	m._v = state["v"]
	m._held_a = state["held_a"]
	m._held_b = state["held_b"]
	m._cur_a = state["cur_a"]
	m._cur_b = state["cur_b"]
	m._n_a = state["n_a"]
	m._n_b = Vector2.ZERO if state["cur_b"] == ContactId.NONE else Vector2(0.6, 0.8)
	return m


# The readable path: what _touch_ring() did before the slide was written out.
func _readable(m: BallMover) -> void:
	var d: Vector2 = m._p - m._ring_center
	var dist: float = sqrt(d.length_squared())
	var nrm: Vector2 = -d / dist
	m._p = m._ring_center + d * (m._ring_lim / dist)
	var bounced: bool = m.respond(
		ContactId.RING, m._ring_center, d, nrm, m._ring_lim, BallMover.Surface.RING, 0
	)
	if bounced and absf(m._v.x) < m._ring_min_speed_x:
		m._v.x = m._ring_min_speed_x if m._v.x >= 0.0 else -m._ring_min_speed_x


func _random_state(rng: RandomNumberGenerator) -> Dictionary:
	var center := Vector2(rng.randf_range(-50, 400), rng.randf_range(-50, 400))
	var lim := rng.randf_range(40.0, 400.0)
	var dir := Vector2.from_angle(rng.randf_range(-PI, PI))
	var ids := [ContactId.NONE, ContactId.RING, OTHER_A, OTHER_B]
	var speed := rng.randf_range(0.0, 1600.0) if rng.randf() < 0.9 else rng.randf_range(0, 2)
	return {
		"center": center,
		"lim": lim,
		"min_x": rng.randf_range(0.0, 40.0),
		"gravity": Vector2(rng.randf_range(-300, 300), rng.randf_range(0, 1000)),
		"substeps": rng.randi_range(1, 4),
		"threshold": rng.randf_range(0.0, 60.0),
		"e": rng.randf_range(0.0, 1.0),
		"keep": rng.randf_range(0.0, 1.0),
		"p": center + dir * (lim + rng.randf_range(0.0, 3.0)),
		"v": Vector2.from_angle(rng.randf_range(-PI, PI)) * speed,
		"held_a": ids[rng.randi_range(0, 3)],
		"held_b": ids[rng.randi_range(0, 3)],
		"cur_a": ids[rng.randi_range(0, 3)],
		"cur_b": [ContactId.NONE, OTHER_B][rng.randi_range(0, 1)],
		"n_a": Vector2(0.0, -1.0),
	}


# The edge cases: at rest, moving along the ring (no normal speed), straight into it (no
# tangential speed), exactly at the bounce threshold, held from behind, a zero threshold.
func _edge_states() -> Array[Dictionary]:
	var rng := RandomNumberGenerator.new()
	rng.seed = 5
	var out: Array[Dictionary] = []
	var base := _random_state(rng)
	base["gravity"] = Vector2(0, 777.78)
	base["center"] = Vector2(350, 350)
	base["lim"] = 300.0
	base["p"] = Vector2(350, 350) + Vector2(0.6, -0.8) * 301.0
	var outward := Vector2(0.6, -0.8)
	for v: Vector2 in [
		Vector2.ZERO,
		Vector2(0.8, 0.6) * 500.0,
		outward * 500.0,
		outward * 30.0,
		outward * (30.0 + 0.8 * 777.78 / 120.0),
		outward * 1e-4,
		outward * 500.0 + Vector2(0.8, 0.6) * 1e-3,
	]:
		for held: int in [ContactId.NONE, ContactId.RING]:
			for threshold: float in [30.0, 0.0]:
				var s := base.duplicate()
				s["v"] = v
				s["held_b"] = held
				s["held_a"] = ContactId.NONE
				s["cur_a"] = ContactId.NONE
				s["cur_b"] = ContactId.NONE
				s["threshold"] = threshold
				out.append(s)
	return out


func _assert_same(state: Dictionary, what: String) -> bool:
	var a := _mover(state)
	var b := _mover(state)
	a._touch_ring()
	_readable(b)
	var same: bool = (
		a._p == b._p
		and a._v == b._v
		and a._cur_a == b._cur_a
		and a._cur_b == b._cur_b
		and a._n_a == b._n_a
		and a._n_b == b._n_b
		and a.events == b.events
		and a.event_speed == b.event_speed
	)
	if not same:
		assert_true(same, "%s: %s" % [what, state])
	return same


func test_the_written_out_ring_slide_is_respond_bit_for_bit() -> void:
	var rng := RandomNumberGenerator.new()
	rng.seed = 46
	var failed := 0
	for k in CASES:
		if not _assert_same(_random_state(rng), "case %d" % k):
			failed += 1
			if failed > 5:
				break
	assert_eq(failed, 0, "random contacts")


func test_the_edge_cases_match_too() -> void:
	var failed := 0
	var states := _edge_states()
	for k in states.size():
		if not _assert_same(states[k], "edge %d" % k):
			failed += 1
	assert_eq(failed, 0, "edge cases")
	assert_gt(states.size(), 20)
