extends GutTest
## BallMover.move_range() runs the capsule-wall search of a substep written out (a call per
## substep of a maze ball cost about a fifth of its motion): the deepest wall first, then
## again while more than one touched (up to three times), with the held flat-side slide,
## the slide and the bounce as _touch_walls() answers them. Pinned here bit for bit to
## _touch_walls() (itself pinned to respond() by test_wall_slide.gd): the same ball moved
## over the same walls with the copy and with the call (BallMover.walls_written_out off)
## must leave every ball field, event and contact identical. Random walls, balls, speeds,
## held contacts and tunings, and the edge cases: at rest, exactly at the bounce threshold,
## held from behind, grazing, in a wall's cap with either cap contact, centre on the
## segment, a post (a zero-length wall), a corner of two and three walls, near a wall but
## not touching it, and a fast ball that substeps.

const CASES := 10000
const DT := 1.0 / 120.0
const GRAVITY_Y := 777.78

var _wheels := Windmills.new()


## One ball moved by one mover over `geo`: returns the store after the move, and the
## mover's events, as one array of comparable values.
func _moved(geo: StaticGeometry, t: PhysicsTuning, ball: Dictionary, copy: bool) -> Array:
	var b := BallStore.new()
	b.add(ball["p"], ball["v"], ball["r"])
	b.contact_a[0] = ball["held_a"]
	b.contact_b[0] = ball["held_b"]
	b.push[0] = ball["push"]
	var m := BallMover.new()
	m.walls_written_out = copy
	var hits := PackedByteArray([1, 1, 1, 1])
	m.begin(b, geo, _wheels, t, ball["gravity"], Vector2.ZERO, DT, true, hits)
	m.move_range(0, 1)
	return [
		b.pos,
		b.vel,
		b.contact_a,
		b.contact_b,
		b.support_static,
		b.support_static2,
		b.rest,
		b.asleep,
		b.alive,
		m.events,
		m.event_speed,
	]


func _same(geo: StaticGeometry, t: PhysicsTuning, ball: Dictionary, what: String) -> bool:
	var copy: Array = _moved(geo, t, ball, true)
	var readable: Array = _moved(geo, t, ball, false)
	var same: bool = copy == readable
	if not same:
		var got := "written out %s, readable %s" % [copy, readable]
		assert_true(same, "%s: %s: %s" % [what, ball, got])
	return same


func _tuning(threshold: float, glance: bool, e: float, keep: float) -> PhysicsTuning:
	var t := PhysicsTuning.new()
	t.bounce_threshold = threshold
	t.wall_cap_contact = (
		PhysicsTuning.CapContact.GLANCE if glance else PhysicsTuning.CapContact.ROLL_ROUND
	)
	t.wall_restitution = e
	t.restitution = e
	t.tangent_friction = keep
	return t


func _random_tuning(rng: RandomNumberGenerator) -> PhysicsTuning:
	return _tuning(
		rng.randf_range(0.0, 60.0),
		rng.randf() < 0.3,
		rng.randf_range(0.0, 1.0),
		rng.randf_range(0.0, 1.0)
	)


## A few random capsules (now and then a post) in a 120 px square, binned for `r`.
func _random_walls(rng: RandomNumberGenerator, r: float) -> StaticGeometry:
	var geo := StaticGeometry.new()
	for _k: int in rng.randi_range(1, 6):
		var a := Vector2(rng.randf_range(0, 120), rng.randf_range(0, 120))
		var length: float = rng.randf_range(0.0, 80.0) if rng.randf() < 0.9 else 0.0
		var b: Vector2 = a + Vector2.from_angle(rng.randf_range(-PI, PI)) * length
		geo.shapes.add_wall(a, b, rng.randf_range(1.0, 12.0))
	geo.build(r)
	return geo


## A ball near a random wall of `geo` (before its end, on it or past it; at some depth up
## to a little past touching), with a random speed, gravity, push and held contacts.
func _random_ball(rng: RandomNumberGenerator, geo: StaticGeometry, r: float) -> Dictionary:
	var s: StaticShapes = geo.shapes
	var w: int = rng.randi_range(0, s.wall_a.size() - 1)
	var along: Vector2 = s.wall_a[w].lerp(s.wall_b[w], rng.randf_range(-0.3, 1.3))
	var q: Vector2 = Geometry2D.get_closest_point_to_segment(along, s.wall_a[w], s.wall_b[w])
	var dir := Vector2.from_angle(rng.randf_range(-PI, PI))
	var p: Vector2 = q + dir * (s.wall_radius[w] + r) * rng.randf_range(0.0, 1.1)
	var speed := rng.randf_range(0.0, 1600.0) if rng.randf() < 0.8 else rng.randf_range(0, 2)
	var ids: Array[int] = [ContactId.NONE, _wall_id(w), _wall_id(rng.randi_range(0, 5))]
	var push := Vector2.ZERO
	if rng.randf() < 0.2:
		push = Vector2.from_angle(rng.randf_range(-PI, PI)) * rng.randf_range(0.0, r)
	return {
		"p": p,
		"v": Vector2.from_angle(rng.randf_range(-PI, PI)) * speed,
		"r": r,
		"gravity": Vector2(rng.randf_range(-300, 300), rng.randf_range(-100, 1000)),
		"held_a": ids[rng.randi_range(0, 2)],
		"held_b": ids[rng.randi_range(0, 2)],
		"push": push,
	}


func _wall_id(w: int) -> int:
	return (w << ContactId.KIND_BITS) | ContactId.KIND_WALL


func test_the_written_out_wall_search_is_touch_walls_bit_for_bit() -> void:
	var rng := RandomNumberGenerator.new()
	rng.seed = 436
	var failed := 0
	var touched := 0
	var r := 5.0
	var geo := _random_walls(rng, r)
	var t := _random_tuning(rng)
	for k in CASES:
		if k % 50 == 0:
			r = [3.0, 5.0, 7.5][rng.randi_range(0, 2)]
			geo = _random_walls(rng, r)
			t = _random_tuning(rng)
		var ball := _random_ball(rng, geo, r)
		if not _same(geo, t, ball, "case %d" % k):
			failed += 1
			if failed > 5:
				break
		var moved: Array = _moved(geo, t, ball, true)
		if moved[2][0] != ball["held_a"] or moved[9].size() > 0:
			touched += 1
	assert_eq(failed, 0, "random balls")
	# Most cases touch a wall (a new contact, or a bounce), or the test would pin little.
	assert_gt(touched, CASES / 2, "contacts answered")


## A flat wall (y = 100 from x = 0 to 200, radius 4), a post at (300, 50), a corner of two
## walls at (0, 300) and a corner of three at (200, 300), for balls of radius 5.
func _edge_walls() -> StaticGeometry:
	var geo := StaticGeometry.new()
	geo.shapes.add_wall(Vector2(0, 100), Vector2(200, 100), 4.0)
	geo.shapes.add_wall(Vector2(300, 50), Vector2(300, 50), 4.0)
	geo.shapes.add_wall(Vector2(0, 300), Vector2(100, 300), 4.0)
	geo.shapes.add_wall(Vector2(0, 300), Vector2(0, 200), 4.0)
	geo.shapes.add_wall(Vector2(200, 300), Vector2(300, 300), 4.0)
	geo.shapes.add_wall(Vector2(200, 300), Vector2(200, 200), 4.0)
	geo.shapes.add_wall(Vector2(200, 300), Vector2(140, 240), 4.0)
	geo.build(5.0)
	return geo


# Each place, with: at rest, sliding along, straight in, exactly at the bounce threshold
# (gravity's approach not counted), a hair faster, grazing, fast enough to substep; held
# from behind or not; both cap contacts; a zero threshold.
func test_the_edge_cases_match_too() -> void:
	var geo := _edge_walls()
	var gravity := Vector2(0.0, GRAVITY_Y)
	var threshold := 30.0
	# Place, the wall it touches (its normal there), the wall's id for "held".
	var places: Array = [
		[Vector2(100, 91.0), Vector2(0, -1), 0],  # on the side, 1 px deep
		[Vector2(100, 91.0 + 1e-4), Vector2(0, -1), 0],  # grazing depth
		[Vector2(100, 91.0 - 1e-4), Vector2(0, -1), 0],  # a hair clear of it
		[Vector2(-6.0, 94.0), Vector2(-0.7071, -0.7071), 0],  # in the cap at a
		[Vector2(207.0, 100.0), Vector2(1, 0), 0],  # in the cap at b, level
		[Vector2(100, 100), Vector2(0, -1), 0],  # centre on the segment
		[Vector2(303, 44), Vector2(0.4472, -0.8944), 1],  # a post
		[Vector2(300, 50), Vector2(0, -1), 1],  # a post, centre on it
		[Vector2(8, 292), Vector2(0.7071, -0.7071), 2],  # a corner of two walls
		[Vector2(193, 292), Vector2(-0.7071, -0.7071), 4],  # a corner of three walls
		[Vector2(100, 70), Vector2(0, -1), 0],  # near the wall, not touching
	]
	var failed := 0
	var count := 0
	for place: Array in places:
		var nrm: Vector2 = place[1]
		var into: Vector2 = -nrm
		var along := Vector2(-nrm.y, nrm.x)
		var gn: float = minf(gravity.dot(nrm) * DT, 0.0)
		for v: Vector2 in [
			Vector2.ZERO,
			along * 300.0,
			into * 300.0,
			into * (threshold + gn),
			into * (threshold + gn + 1e-3),
			along * 300.0 + into * 1e-4,
			into * 1e-6,
			into * 1500.0 + along * 200.0,
		]:
			for held: int in [ContactId.NONE, _wall_id(place[2])]:
				for glance: bool in [false, true]:
					for th: float in [threshold, 0.0]:
						var ball := {
							"p": place[0],
							"v": v,
							"r": 5.0,
							"gravity": gravity,
							"held_a": ContactId.NONE,
							"held_b": held,
							"push": Vector2.ZERO,
						}
						count += 1
						if not _same(geo, _tuning(th, glance, 0.4, 0.9), ball, "edge %d" % count):
							failed += 1
	assert_eq(failed, 0, "edge cases")
	assert_eq(count, places.size() * 8 * 8)
