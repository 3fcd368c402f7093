extends GutTest
## Sleeping: a ball that rests for tuning.sleep_time is skipped until something wakes it
## (a ball hitting it faster than rest_speed, gravity changing, a ball moved or removed).

const CENTER := Vector2(500, 500)
const RING_R := 200.0
const BALL_R := 5.0


func _ring_world() -> BallWorld:
	var t := TuningPresets.pachinko()
	t.min_horizontal_speed = 0.0
	var w := BallWorld.new(t)
	w.shapes.set_ring(CENTER, RING_R)
	return w


func _bottom() -> Vector2:
	return CENTER + Vector2(0, RING_R - BALL_R)


func _steps(w: BallWorld, n: int) -> void:
	for _i: int in n:
		w.step(1.0 / 120.0)


func test_a_resting_ball_falls_asleep_and_keeps_its_place() -> void:
	var w := _ring_world()
	var id := w.spawn_ball(_bottom(), Vector2.ZERO, BALL_R)
	_steps(w, 6)
	assert_false(w.is_ball_asleep(id), "not before sleep_time")
	_steps(w, 60)
	assert_true(w.is_ball_asleep(id))
	var p := w.get_ball_position(id)
	var rested := w.get_ball_rest_time(id)
	_steps(w, 120)
	assert_eq(w.get_ball_position(id), p, "a sleeper does not move")
	assert_eq(w.get_ball_velocity(id), Vector2.ZERO, "nor carry gravity's speed")
	assert_almost_eq(w.get_ball_rest_time(id), rested + 1.0, 1e-3, "rest time keeps growing")


func test_sleep_time_zero_never_sleeps() -> void:
	var w := _ring_world()
	w.tuning.sleep_time = 0.0
	var id := w.spawn_ball(_bottom(), Vector2.ZERO, BALL_R)
	_steps(w, 240)
	assert_false(w.is_ball_asleep(id))


func test_a_falling_ball_wakes_a_sleeper_and_shares_momentum() -> void:
	var t := TuningPresets.pachinko()
	t.gravity = Vector2.ZERO
	t.min_horizontal_speed = 0.0
	t.ball_restitution = 1.0
	var w := BallWorld.new(t)
	var still := w.spawn_ball(Vector2(100, 0), Vector2.ZERO, BALL_R)
	_steps(w, 30)
	assert_true(w.is_ball_asleep(still), "a ball at rest in empty space sleeps")
	var mover := w.spawn_ball(Vector2(0, 0), Vector2(150, 0), BALL_R)
	_steps(w, 120)
	assert_false(w.is_ball_asleep(still) and w.get_ball_position(still) == Vector2(100, 0))
	assert_almost_eq(w.get_ball_velocity(still).x, 150.0, 0.5, "elastic: it takes the speed")
	assert_almost_eq(w.get_ball_velocity(mover).x, 0.0, 0.5, "and the mover stops")


func test_a_slow_touch_does_not_wake_a_sleeper() -> void:
	var t := TuningPresets.pachinko()
	t.gravity = Vector2.ZERO
	var w := BallWorld.new(t)
	var still := w.spawn_ball(Vector2(100, 0), Vector2.ZERO, BALL_R)
	_steps(w, 30)
	var slow := t.rest_speed * 0.5
	w.spawn_ball(Vector2(88, 0), Vector2(slow, 0), BALL_R)
	_steps(w, 120)
	assert_true(w.is_ball_asleep(still))
	assert_eq(w.get_ball_position(still), Vector2(100, 0))


func test_changing_gravity_wakes_every_sleeper() -> void:
	var w := _ring_world()
	var id := w.spawn_ball(_bottom(), Vector2.ZERO, BALL_R)
	_steps(w, 60)
	assert_true(w.is_ball_asleep(id))
	w.gravity = Vector2(400, 400)
	_steps(w, 1)
	assert_false(w.is_ball_asleep(id))
	_steps(w, 30)
	assert_gt(w.get_ball_position(id).x, _bottom().x + 1.0, "it rolls with the new gravity")


func test_removing_a_ball_wakes_the_ones_it_held_up() -> void:
	var w := _ring_world()
	var low := w.spawn_ball(_bottom(), Vector2.ZERO, BALL_R)
	var high := w.spawn_ball(_bottom() - Vector2(0, 2.0 * BALL_R), Vector2.ZERO, BALL_R)
	_steps(w, 120)
	assert_true(w.is_ball_asleep(high), "the stack went to sleep")
	var y := w.get_ball_position(high).y
	w.remove_ball(low)
	_steps(w, 60)
	assert_gt(w.get_ball_position(high).y, y + BALL_R, "with its support gone it falls")


func test_moving_a_ball_by_hand_wakes_it() -> void:
	var w := _ring_world()
	var id := w.spawn_ball(_bottom(), Vector2.ZERO, BALL_R)
	_steps(w, 60)
	w.set_ball_velocity(id, Vector2(300, 0))
	assert_false(w.is_ball_asleep(id))
	_steps(w, 1)
	assert_gt(w.get_ball_position(id).x, _bottom().x)


func test_a_sleeper_whose_ball_support_is_knocked_away_falls() -> void:
	var t := TuningPresets.pachinko()
	t.min_horizontal_speed = 0.0
	# Elastic: the hitter stops dead where the lower ball was, clear of the upper one.
	t.ball_restitution = 1.0
	var w := BallWorld.new(t)
	# A flat floor; its top is at y = 95.
	w.shapes.add_wall(Vector2(0, 100), Vector2(1000, 100), 5.0)
	var low := w.spawn_ball(Vector2(500, 90), Vector2.ZERO, BALL_R)
	var high := w.spawn_ball(Vector2(500, 80), Vector2.ZERO, BALL_R)
	_steps(w, 120)
	assert_true(w.is_ball_asleep(high), "the stack went to sleep")
	var y := w.get_ball_position(high).y
	# A fast ball along the floor knocks the lower ball away without touching the upper.
	var hitter := w.spawn_ball(Vector2(400, 90), Vector2(600, 0), BALL_R)
	_steps(w, 60)
	assert_lt(w.get_ball_position(hitter).x, 500.0 - BALL_R, "the hitter stopped short")
	assert_gt(w.get_ball_position(low).x, 500.0 + BALL_R, "the lower ball was knocked away")
	assert_gt(w.get_ball_position(high).y, y + BALL_R, "the upper one does not hang in the air")
