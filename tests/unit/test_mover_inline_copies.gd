extends GutTest
## Two more written-out copies in BallMover.move_range() (each call was part of a quarter of
## a contact-free step), pinned bit for bit to their readable rules over random balls and
## the edge cases:
## - the substep count of a ball with no push and no windmill about, to _substeps();
## - a moving ball's zone-edge test on a board with zones alone, to
##   BallSensors.crossed_zone_edge() (then BallSensors.sense(), as the mover's loop does).
## The mover moves one ball on a board with nothing it can touch, so the ball goes straight.

const CASES := 10000
const DT := 1.0 / 120.0

var _wheels := Windmills.new()
var _tuning := PhysicsTuning.new()


## A mover that has moved one ball of radius `r` from `p` at `v` (zone bits `mask`) over
## `geo`.
func _moved(geo: StaticGeometry, p: Vector2, v: Vector2, r: float, mask: int) -> BallMover:
	var b := BallStore.new()
	b.add(p, v, r)
	b.zone_mask[0] = mask
	var m := BallMover.new()
	var hits := PackedByteArray([1, 1, 1, 1])
	m.begin(b, geo, _wheels, _tuning, Vector2.ZERO, Vector2.ZERO, DT, false, hits)
	m.move_range(0, 1)
	return m


func _empty_geometry(r: float) -> StaticGeometry:
	var geo := StaticGeometry.new()
	geo.build(r)
	return geo


# The substeps: the mover's substep time against _substeps() for the same ball.
func _same_substeps(geo: StaticGeometry, v: Vector2, r: float, what: String) -> bool:
	var m := _moved(geo, Vector2.ZERO, v, r, 0)
	var readable := BallMover.new()
	var b := BallStore.new()
	b.add(Vector2.ZERO, v, r)
	var hits := PackedByteArray([1, 1, 1, 1])
	readable.begin(b, geo, _wheels, _tuning, Vector2.ZERO, Vector2.ZERO, DT, false, hits)
	readable._set_radius(r)
	readable._v = m._vel[0]
	var steps: int = readable._substeps(Vector2.ZERO)
	var same: bool = m._h == DT / steps
	if not same:
		assert_true(same, "%s: v %s r %s: h %s, readable %d steps" % [what, v, r, m._h, steps])
	return same


func test_the_written_out_substep_count_is_substeps_bit_for_bit() -> void:
	var rng := RandomNumberGenerator.new()
	rng.seed = 434
	var geos := {}
	var failed := 0
	for k in CASES:
		var r: float = [3.0, 5.0, 7.5][rng.randi_range(0, 2)]
		if not geos.has(r):
			geos[r] = _empty_geometry(r)
		var speed := rng.randf_range(0.0, 1600.0) if rng.randf() < 0.9 else rng.randf_range(0, 2)
		var v: Vector2 = Vector2.from_angle(rng.randf_range(-PI, PI)) * speed
		if not _same_substeps(geos[r], v, r, "case %d" % k):
			failed += 1
			if failed > 5:
				break
	assert_eq(failed, 0, "random balls")


# At rest, and exactly at one, two and many substeps' travel (straight and diagonal), a
# hair either side of it, and at the top speed.
func test_the_substep_edge_cases_match_too() -> void:
	var r := 5.0
	var geo := _empty_geometry(r)
	var travel: float = geo.max_travel(r, BallMover.TRAVEL_SHARE)
	var failed := 0
	var count := 0
	for dir: Vector2 in [Vector2(1, 0), Vector2(0, -1), Vector2(0.6, 0.8), Vector2(-0.8, 0.6)]:
		for times: float in [0.0, 1.0, 2.0, 3.0, 7.0, 100.0]:
			for nudge: float in [0.0, 1e-9, -1e-9, 1e-4]:
				var v: Vector2 = dir * (travel * times / DT + nudge)
				count += 1
				if not _same_substeps(geo, v, r, "edge %s x%s %s" % [dir, times, nudge]):
					failed += 1
	assert_eq(failed, 0, "edge cases")
	assert_gt(count, 90)


func _zone_geometry(rng: RandomNumberGenerator, r: float) -> StaticGeometry:
	var geo := StaticGeometry.new()
	for k: int in rng.randi_range(1, 4):
		var c := Vector2(rng.randf_range(0, 60), rng.randf_range(0, 60))
		geo.shapes.add_sensor(StaticShapes.SENSOR_ZONE, c, rng.randf_range(2.0, 30.0))
	geo.build(r)
	return geo


# The zones: the mover's events and zone bits against the readable pass on the same move.
func _same_zone_pass(geo: StaticGeometry, p: Vector2, v: Vector2, mask: int, what: String) -> bool:
	var r := 5.0
	var m := _moved(geo, p, v, r, mask)
	var p_end: Vector2 = m._pos[0]
	var zone_mask := PackedInt32Array([mask])
	var goal_mask := PackedInt32Array([0])
	var ev := PackedInt32Array()
	var evs := PackedFloat32Array()
	var s: StaticShapes = geo.shapes
	if BallSensors.crossed_zone_edge(p_end, mask, s.zone_pos, s.zone_radius):
		BallSensors.sense(s, 0, 0, p, p_end, goal_mask, zone_mask, ev, evs)
	var same: bool = m.events == ev and m.event_speed == evs and m._zone_mask == zone_mask
	if not same:
		var got := "written out %s %s, readable %s %s" % [m.events, m._zone_mask, ev, zone_mask]
		assert_true(same, "%s: p %s v %s mask %d: %s" % [what, p, v, mask, got])
	return same


func test_the_written_out_zone_edge_test_is_crossed_zone_edge_bit_for_bit() -> void:
	var rng := RandomNumberGenerator.new()
	rng.seed = 435
	var failed := 0
	var crossed := 0
	var geo := _zone_geometry(rng, 5.0)
	for k in CASES:
		if k % 100 == 0:
			geo = _zone_geometry(rng, 5.0)
		var p := Vector2(rng.randf_range(-10, 70), rng.randf_range(-10, 70))
		var speed := rng.randf_range(0.0, 1600.0) if rng.randf() < 0.9 else rng.randf_range(0, 2)
		var v: Vector2 = Vector2.from_angle(rng.randf_range(-PI, PI)) * speed
		var mask: int = rng.randi_range(0, 15)
		if not _same_zone_pass(geo, p, v, mask, "case %d" % k):
			failed += 1
			if failed > 5:
				break
		if _moved(geo, p, v, 5.0, mask)._zone_mask[0] != mask:
			crossed += 1
	assert_eq(failed, 0, "random moves")
	# Enough moves cross an edge (or start with bits that are wrong) to pin the test.
	assert_gt(crossed, CASES / 10, "edges crossed")


# A ball ending exactly on a zone's edge (inside counts), a hair inside and outside,
# entering, leaving, staying in and staying out, at rest and moving (the rest speed is the
# tuning's: below it the readable pass runs anyway).
func test_the_zone_edge_cases_match_too() -> void:
	var geo := StaticGeometry.new()
	geo.shapes.add_sensor(StaticShapes.SENSOR_ZONE, Vector2(100, 100), 20.0)
	geo.shapes.add_sensor(StaticShapes.SENSOR_ZONE, Vector2(130, 100), 10.0)
	geo.build(5.0)
	var rest: float = _tuning.rest_speed
	var failed := 0
	var count := 0
	for end: Vector2 in [
		Vector2(120, 100), Vector2(120 - 1e-4, 100), Vector2(120 + 1e-4, 100), Vector2(100, 100)
	]:
		for v: Vector2 in [Vector2.ZERO, Vector2(rest, 0), Vector2(600, 0), Vector2(-600, 300)]:
			for mask: int in [0, 1, 2, 3]:
				count += 1
				if not _same_zone_pass(
					geo, end - v * DT, v, mask, "edge %s %s %d" % [end, v, mask]
				):
					failed += 1
	assert_eq(failed, 0, "edge cases")
	assert_eq(count, 64)
