extends GutTest
## BallWorld against pins: bounce speed and angle, the Flash minimum horizontal speed,
## special pins pocketing a ball exactly once, pin_hit for sound.

const DT := 1.0 / 2000.0


func _world() -> BallWorld:
	var t := TuningPresets.pachinko()
	t.gravity = Vector2.ZERO
	var w := BallWorld.new(t)
	return w


func _run(w: BallWorld, seconds: float) -> void:
	for _i: int in int(seconds / DT):
		w.step(DT)


func test_head_on_bounce_keeps_restitution_of_the_speed() -> void:
	var w := _world()
	w.shapes.add_pin(Vector2(0, 0), 1.5)
	var id := w.spawn_ball(Vector2(0, -30), Vector2(0, 300), 5.0)
	_run(w, 0.2)
	var v := w.get_ball_velocity(id)
	assert_almost_eq(v.y, -300.0 * 0.6, 0.5, "normal speed scaled by restitution 0.6")
	assert_almost_eq(v.x, 0.0, 0.01)


func test_oblique_bounce_reflects_normal_and_scales_tangent() -> void:
	var w := _world()
	w.shapes.add_pin(Vector2(0, 0), 1.5)
	var lim := 6.5
	var off := lim * sin(PI / 4.0)
	var id := w.spawn_ball(Vector2(-off, -40), Vector2(0, 400), 5.0)
	_run(w, 0.2)
	var v := w.get_ball_velocity(id)
	# Normal at 45°: vn = 400·cos45 → -0.6·vn; tangent 400·sin45 → ×0.6 (tangent_friction).
	var nrm := Vector2(-1, -1).normalized()
	var tan := Vector2(1, -1).normalized()
	var vn := v.dot(nrm)
	var vt := v.dot(tan)
	assert_almost_eq(vn, 0.6 * 400.0 * cos(PI / 4.0), 6.0, "normal component")
	assert_almost_eq(absf(vt), 0.6 * 400.0 * sin(PI / 4.0), 6.0, "tangent component")
	assert_lt(v.x, 0.0, "bounced to the left of a pin hit on its left side")


func test_pin_hit_reports_index_and_normal_speed_once() -> void:
	var w := _world()
	w.shapes.add_pin(Vector2(100, 0), 1.5)
	var pin := w.shapes.add_pin(Vector2(0, 0), 1.5)
	var hits: Array = []
	w.pin_hit.connect(func(b: int, p: int, s: float) -> void: hits.append([b, p, s]))
	var id := w.spawn_ball(Vector2(0, -30), Vector2(0, 300), 5.0)
	_run(w, 0.15)
	assert_eq(hits.size(), 1)
	assert_eq(hits[0][0], id)
	assert_eq(hits[0][1], pin)
	assert_almost_eq(float(hits[0][2]), 300.0, 1.0)


func test_min_horizontal_speed_pushes_a_ball_off_a_pin_top() -> void:
	var w := _world()
	w.gravity = Vector2(0, 778)
	w.shapes.add_pin(Vector2(0, 0), 1.5, -1, false, 0.5 / PhysicsTuning.FLASH_TICK)
	var id := w.spawn_ball(Vector2(0, -6.6), Vector2.ZERO, 5.0)
	_run(w, 0.3)
	var p := w.get_ball_position(id)
	assert_gt(absf(p.x), 1.0, "no ball balances on a pin top")
	assert_gt(p.y, 0.0, "it rolled off and fell")


func test_min_horizontal_speed_is_the_pins_own_material() -> void:
	var w := _world()
	w.gravity = Vector2(0, 778)
	w.tuning.min_horizontal_speed = 0.5 / PhysicsTuning.FLASH_TICK  # not read by the world
	w.shapes.add_pin(Vector2(0, 0), 1.5)
	var id := w.spawn_ball(Vector2(0, -6.6), Vector2.ZERO, 5.0)
	_run(w, 0.3)
	assert_almost_eq(w.get_ball_position(id).x, 0.0, 1e-3, "a plain pin lets a ball rest on top")


func test_a_negative_min_speed_is_refused() -> void:
	var w := _world()
	assert_eq(w.shapes.add_pin(Vector2.ZERO, 1.5, -1, false, -1.0), -1)
	assert_push_error("min_speed_x")


func test_special_pin_pockets_once_and_removes_the_ball() -> void:
	var w := _world()
	w.shapes.add_pin(Vector2(0, 0), 1.5, 3, true)
	var got: Array = []
	w.ball_captured.connect(func(b: int, pocket: int) -> void: got.append([b, pocket]))
	var id := w.spawn_ball(Vector2(0, -30), Vector2(0, 300), 5.0)
	_run(w, 0.3)
	assert_eq(got, [[id, 3]])
	assert_false(w.has_ball(id))
	assert_eq(w.ball_count(), 0)


func test_fast_ball_does_not_tunnel_through_a_pin() -> void:
	var t := TuningPresets.pachinko()
	t.gravity = Vector2.ZERO
	t.max_speed = 5000.0
	t.min_horizontal_speed = 0.0
	var w := BallWorld.new(t)
	w.shapes.add_pin(Vector2(0, 0), 1.5)
	var id := w.spawn_ball(Vector2(0, -100), Vector2(0, 4000), 5.0)
	for _i: int in 10:
		w.step(1.0 / 60.0)
	assert_lt(w.get_ball_position(id).y, 0.0, "4,000 px/s at 60 Hz still bounces back")
