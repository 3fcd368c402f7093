extends GutTest
## The contact record (a ball's first contact of the step, or its second; a third replaces
## the second) is written out in BallMover's two slides, on a wall (_touch_walls) and on the
## ring (_touch_ring), a call fewer a contact: pinned here bit for bit to the readable rule,
## BallMover._note_contact(), over random slides and every earlier record (empty, this
## contact already first or second, other contacts in both slots), and the edge cases.
## Both slides here are held contacts, so they slide whatever their speed.

const CASES := 10000
const WALL := 2
const WALL_ID := (WALL << ContactId.KIND_BITS) | ContactId.KIND_WALL
const OTHER_A := (3 << ContactId.KIND_BITS) | ContactId.KIND_PIN
const OTHER_B := (5 << ContactId.KIND_BITS) | ContactId.KIND_WALL
## A flat wall from (0, 100) to (200, 100), radius 4; a ring of radius 300 about (350, 350).
const WALL_A := Vector2(0, 100)
const WALL_AB := Vector2(200, 0)
const WALL_R := 4.0
const RING_CENTER := Vector2(350, 350)
const RING_LIM := 295.0
const BALL_R := 5.0


func _mover(state: Dictionary) -> BallMover:
	var m := BallMover.new()
	m._wall_start = PackedInt32Array([0, 1])
	m._wall_items = PackedInt32Array([WALL])
	m._wall_item_a = PackedVector2Array([WALL_A])
	m._wall_item_ab = PackedVector2Array([WALL_AB])
	m._wall_item_inv = PackedFloat32Array([1.0 / WALL_AB.length_squared()])
	m._wall_item_rad = PackedFloat32Array([WALL_R])
	m._wall_ab = PackedVector2Array([WALL_AB, WALL_AB, WALL_AB])
	m._wall_inv_len2 = PackedFloat32Array([1.0, 1.0, 1.0 / WALL_AB.length_squared()])
	m._ring_center = RING_CENTER
	m._ring_lim = RING_LIM
	m._r = BALL_R
	m._gravity = Vector2(0, 777.78)
	m._dt = 1.0 / 120.0
	m._h = m._dt
	m._threshold = 30.0
	m._hits_heard = PackedByteArray([1, 1, 1, 1])
	m._ids = PackedInt32Array([7])
	m._p = state["p"]
	m._v = state["v"]
	m._held_a = WALL_ID if state["wall"] else ContactId.RING
	m._cur_a = state["cur_a"]
	m._cur_b = state["cur_b"]
	m._n_a = state["n_a"]
	m._n_b = state["n_b"]
	return m


# The readable rule: the contact's normal, and if the ball moves into the surface,
# _note_contact().
func _readable(m: BallMover, wall: bool) -> void:
	var id: int = WALL_ID if wall else ContactId.RING
	var nrm: Vector2
	if wall:
		var s: float = clampf((m._p - WALL_A).dot(WALL_AB) * m._wall_item_inv[0], 0.0, 1.0)
		var d: Vector2 = m._p - (WALL_A + WALL_AB * s)
		nrm = d / sqrt(d.length_squared())
	else:
		var d: Vector2 = m._p - RING_CENTER
		nrm = -d / sqrt(d.length_squared())
	if m._v.dot(nrm) < 0.0:
		m._note_contact(id, nrm)


func _state(wall: bool, p: Vector2, v: Vector2, cur_a: int, cur_b: int, rng_n: Array) -> Dictionary:
	return {
		"wall": wall,
		"p": p,
		"v": v,
		"cur_a": cur_a,
		"cur_b": cur_b,
		"n_a": Vector2.ZERO if cur_a == ContactId.NONE else rng_n[0],
		"n_b": Vector2.ZERO if cur_b == ContactId.NONE else rng_n[1],
	}


func _random_state(rng: RandomNumberGenerator) -> Dictionary:
	var wall: bool = rng.randf() < 0.5
	var p: Vector2
	if wall:
		var side: float = -1.0 if rng.randf() < 0.5 else 1.0
		p = Vector2(rng.randf_range(1.0, 199.0), 100.0 + side * rng.randf_range(0.1, 8.99))
	else:
		var dist: float = RING_LIM + rng.randf_range(1e-4, 3.0)
		p = RING_CENTER + Vector2.from_angle(rng.randf_range(-PI, PI)) * dist
	var speed := rng.randf_range(0.0, 1600.0) if rng.randf() < 0.9 else rng.randf_range(0, 2)
	var v: Vector2 = Vector2.from_angle(rng.randf_range(-PI, PI)) * speed
	var id: int = WALL_ID if wall else ContactId.RING
	var firsts: Array[int] = [ContactId.NONE, id, OTHER_A, OTHER_B]
	var seconds: Array[int] = [ContactId.NONE, id, OTHER_B]
	var normals: Array = [
		Vector2.from_angle(rng.randf_range(-PI, PI)), Vector2.from_angle(rng.randf_range(-PI, PI))
	]
	var cur_a: int = firsts[rng.randi_range(0, 3)]
	var cur_b: int = seconds[rng.randi_range(0, 2)] if cur_a != ContactId.NONE else ContactId.NONE
	return _state(wall, p, v, cur_a, cur_b, normals)


# Every earlier record on both surfaces, for a ball at rest, sliding along, pressing
# straight in, and grazing (a hair of normal speed).
func _edge_states() -> Array[Dictionary]:
	var out: Array[Dictionary] = []
	var normals: Array = [Vector2(0.0, -1.0), Vector2(0.6, 0.8)]
	for wall: bool in [true, false]:
		var p: Vector2 = Vector2(100, 92) if wall else RING_CENTER + Vector2(0.6, 0.8) * 296.0
		var nrm: Vector2 = Vector2(0, -1) if wall else Vector2(-0.6, -0.8)
		var along := Vector2(-nrm.y, nrm.x)
		var id: int = WALL_ID if wall else ContactId.RING
		for v: Vector2 in [
			Vector2.ZERO, along * 300.0, -nrm * 300.0, along * 300.0 - nrm * 1e-4, -nrm * 1e-6
		]:
			for cur_a: int in [ContactId.NONE, id, OTHER_A, OTHER_B]:
				for cur_b: int in [ContactId.NONE, id, OTHER_B]:
					out.append(_state(wall, p, v, cur_a, cur_b, normals))
	return out


func _assert_same(state: Dictionary, what: String) -> bool:
	var a := _mover(state)
	var b := _mover(state)
	if state["wall"]:
		a._touch_walls(0)
	else:
		a._touch_ring()
	_readable(b, state["wall"])
	var same: bool = (
		a._cur_a == b._cur_a and a._cur_b == b._cur_b and a._n_a == b._n_a and a._n_b == b._n_b
	)
	if not same:
		var got := "written out %s %s %s %s" % [a._cur_a, a._cur_b, a._n_a, a._n_b]
		var want := "readable %s %s %s %s" % [b._cur_a, b._cur_b, b._n_a, b._n_b]
		assert_true(same, "%s: %s, %s: %s" % [what, got, want, state])
	return same


func test_the_written_out_contact_records_are_note_contact_bit_for_bit() -> void:
	var rng := RandomNumberGenerator.new()
	rng.seed = 432
	var failed := 0
	for k in CASES:
		if not _assert_same(_random_state(rng), "case %d" % k):
			failed += 1
			if failed > 5:
				break
	assert_eq(failed, 0, "random slides")


func test_the_edge_cases_match_too() -> void:
	var failed := 0
	var states := _edge_states()
	for k in states.size():
		if not _assert_same(states[k], "edge %d" % k):
			failed += 1
	assert_eq(failed, 0, "edge cases")
	assert_eq(states.size(), 120)
