extends GutTest
## BallMover._touch_walls() answers a ball sliding on a capsule wall with respond()'s slide
## written out (most moving balls of a maze touch a wall every substep): pinned here bit
## for bit to the readable path, the ball put back on the wall at its closest point and
## answered by respond(), over random walls, balls and contacts and the edge cases (at rest,
## exactly at the bounce threshold, held from behind, grazing, in a wall's cap with either
## cap contact, centre on the segment, a zero-length wall).

const CASES := 10000
const WALL := 4
const WALL_ID := (WALL << ContactId.KIND_BITS) | ContactId.KIND_WALL
## Contact ids a ball may hold besides the wall's: a pin's, another wall's, the ring's.
const OTHER_A := (3 << ContactId.KIND_BITS) | ContactId.KIND_PIN
const OTHER_B := (5 << ContactId.KIND_BITS) | ContactId.KIND_WALL
const IDS: Array[int] = [ContactId.NONE, WALL_ID, OTHER_A, OTHER_B, ContactId.RING]


## A mover in the middle of a step whose grid has one cell holding the one wall a-b
## (`state` sets it, the ball, its held and current contacts and the constants).
func _mover(state: Dictionary) -> BallMover:
	var m := BallMover.new()
	var a: Vector2 = state["a"]
	var ab: Vector2 = state["b"] - a
	var inv: float = 1.0 / ab.length_squared() if ab != Vector2.ZERO else 0.0
	m._wall_start = PackedInt32Array([0, 1])
	m._wall_items = PackedInt32Array([WALL])
	m._wall_item_a = PackedVector2Array([a])
	m._wall_item_ab = PackedVector2Array([ab])
	m._wall_item_inv = PackedFloat32Array([inv])
	m._wall_item_rad = PackedFloat32Array([state["wall_r"]])
	var wall_ab := PackedVector2Array()
	wall_ab.resize(WALL + 1)
	wall_ab[WALL] = ab
	var inv_len2 := PackedFloat32Array()
	inv_len2.resize(WALL + 1)
	inv_len2[WALL] = inv
	m._wall_ab = wall_ab
	m._wall_inv_len2 = inv_len2
	m._r = state["r"]
	m._gravity = state["gravity"]
	m._dt = 1.0 / 120.0
	m._h = m._dt / state["substeps"]
	m._threshold = state["threshold"]
	m._caps_glance = state["glance"]
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
	m._n_a = Vector2.ZERO if state["cur_a"] == ContactId.NONE else Vector2(0.0, -1.0)
	m._n_b = Vector2.ZERO if state["cur_b"] == ContactId.NONE else Vector2(0.6, 0.8)
	return m


# The readable path: the capsule's closest point to the ball (the segment's, clamped to its
# ends), and if the ball overlaps, the ball put back on the surface there and respond().
func _readable(m: BallMover) -> void:
	var a: Vector2 = m._wall_item_a[0]
	var ab: Vector2 = m._wall_item_ab[0]
	var s: float = clampf((m._p - a).dot(ab) * m._wall_item_inv[0], 0.0, 1.0)
	var q: Vector2 = a + ab * s
	var lim: float = m._wall_item_rad[0] + m._r
	var d: Vector2 = m._p - q
	if d.length_squared() >= lim * lim:
		return
	var nrm := Vector2(0.0, -1.0)
	if d.length_squared() > BallMover.EPS * BallMover.EPS:
		nrm = d / sqrt(d.length_squared())
	elif m._wall_inv_len2[WALL] > 0.0:
		nrm = Vector2(ab.y, -ab.x).normalized()
	var on_cap: bool = s <= 0.0 or s >= 1.0
	var surface: int = BallMover.Surface.WALL_CAP if on_cap else BallMover.Surface.WALL_SIDE
	m._p = q + nrm * lim
	m.respond(WALL_ID, q, d, nrm, lim, surface, WALL)


func _random_state(rng: RandomNumberGenerator) -> Dictionary:
	var a := Vector2(rng.randf_range(-50, 400), rng.randf_range(-50, 400))
	var length: float = rng.randf_range(0.0, 200.0) if rng.randf() < 0.95 else 0.0
	var b: Vector2 = a + Vector2.from_angle(rng.randf_range(-PI, PI)) * length
	var wall_r := rng.randf_range(1.0, 20.0)
	var r := rng.randf_range(3.0, 10.0)
	# A point along the wall (before a, on it, past b), then the ball at some depth from it.
	var along: Vector2 = a.lerp(b, rng.randf_range(-0.3, 1.3))
	var s: float = 0.0
	if length > 0.0:
		s = clampf((along - a).dot(b - a) / (b - a).length_squared(), 0.0, 1.0)
	var q: Vector2 = a.lerp(b, s)
	var dir := Vector2.from_angle(rng.randf_range(-PI, PI))
	var speed := rng.randf_range(0.0, 1600.0) if rng.randf() < 0.9 else rng.randf_range(0, 2)
	return {
		"a": a,
		"b": b,
		"wall_r": wall_r,
		"r": r,
		"gravity": Vector2(rng.randf_range(-300, 300), rng.randf_range(-100, 1000)),
		"substeps": rng.randi_range(1, 4),
		"threshold": rng.randf_range(0.0, 60.0),
		"glance": rng.randf() < 0.3,
		"e": rng.randf_range(0.0, 1.0),
		"keep": rng.randf_range(0.0, 1.0),
		"p": q + dir * (wall_r + r) * rng.randf_range(0.0, 1.05),
		"v": Vector2.from_angle(rng.randf_range(-PI, PI)) * speed,
		"held_a": IDS[rng.randi_range(0, 4)],
		"held_b": IDS[rng.randi_range(0, 4)],
		"cur_a": IDS[rng.randi_range(0, 4)],
		"cur_b": [ContactId.NONE, OTHER_B][rng.randi_range(0, 1)],
	}


# The edge cases on a flat wall (y = 100 from x = 0 to 200, radius 4) with a ball of
# radius 5 on its side, in its caps, and with its centre on the segment; and a post (a
# zero-length wall). Each with: at rest, sliding along it (no normal speed), straight in,
# exactly at the bounce threshold (gravity's approach not counted), a hair faster, grazing
# (a hair of normal speed), held from behind, both cap contacts, a zero threshold.
func _edge_states() -> Array[Dictionary]:
	var out: Array[Dictionary] = []
	var gravity := Vector2(0.0, 777.78)
	var threshold := 30.0
	var places: Array = [
		[Vector2(0, 100), Vector2(200, 100), Vector2(100, 91.0)],  # on its side, 1 px deep
		[Vector2(0, 100), Vector2(200, 100), Vector2(100, 91.0 + 1e-4)],  # grazing depth
		[Vector2(0, 100), Vector2(200, 100), Vector2(-6.0, 94.0)],  # in the cap at a
		[Vector2(0, 100), Vector2(200, 100), Vector2(207.0, 100.0)],  # in the cap at b, level
		[Vector2(0, 100), Vector2(200, 100), Vector2(100, 100)],  # centre on the segment
		[Vector2(50, 50), Vector2(50, 50), Vector2(53, 44)],  # a post
		[Vector2(50, 50), Vector2(50, 50), Vector2(50, 50)],  # a post, centre on it
	]
	for place: Array in places:
		var a: Vector2 = place[0]
		var q: Vector2 = a if place[0] == place[1] else Vector2(clampf(place[2].x, 0, 200), 100)
		var nrm: Vector2 = (place[2] - q).normalized() if place[2] != q else Vector2(0, -1)
		var into: Vector2 = -nrm
		var along := Vector2(-nrm.y, nrm.x)
		var gn: float = minf(gravity.dot(nrm) / 120.0, 0.0)
		for v: Vector2 in [
			Vector2.ZERO,
			along * 300.0,
			into * 300.0,
			into * (threshold + gn),
			into * (threshold + gn + 1e-3),
			along * 300.0 + into * 1e-4,
			into * 1e-6,
		]:
			for held: int in [ContactId.NONE, WALL_ID]:
				for glance: bool in [false, true]:
					for th: float in [threshold, 0.0]:
						out.append(_edge(place, v, held, glance, th, gravity))
	return out


func _edge(
	place: Array, v: Vector2, held: int, glance: bool, threshold: float, gravity: Vector2
) -> Dictionary:
	return {
		"a": place[0],
		"b": place[1],
		"wall_r": 4.0,
		"r": 5.0,
		"gravity": gravity,
		"substeps": 1,
		"threshold": threshold,
		"glance": glance,
		"e": 0.4,
		"keep": 0.9,
		"p": place[2],
		"v": v,
		"held_a": ContactId.NONE,
		"held_b": held,
		"cur_a": ContactId.NONE,
		"cur_b": ContactId.NONE,
	}


func _assert_same(state: Dictionary, what: String) -> bool:
	var a := _mover(state)
	var b := _mover(state)
	a._touch_walls(0)
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
		var got := "written out p %s v %s, readable p %s v %s" % [a._p, a._v, b._p, b._v]
		assert_true(same, "%s: %s: %s" % [what, got, state])
	return same


func test_the_written_out_wall_slide_is_respond_bit_for_bit() -> void:
	var rng := RandomNumberGenerator.new()
	rng.seed = 431
	var failed := 0
	var touched := 0
	for k in CASES:
		var state := _random_state(rng)
		var m := _mover(state)
		m._touch_walls(0)
		if m._p != state["p"] or m._v != state["v"]:
			touched += 1
		if not _assert_same(state, "case %d" % k):
			failed += 1
			if failed > 5:
				break
	assert_eq(failed, 0, "random contacts")
	# Most cases are contacts that change the ball, or the test would pin little.
	assert_gt(touched, CASES / 2, "contacts answered")


func test_the_edge_cases_match_too() -> void:
	var failed := 0
	var states := _edge_states()
	for k in states.size():
		if not _assert_same(states[k], "edge %d" % k):
			failed += 1
	assert_eq(failed, 0, "edge cases")
	assert_gt(states.size(), 300)
