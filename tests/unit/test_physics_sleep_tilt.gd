extends GutTest
## Sleeping under a turning gravity (the maze's tilt): a sleeper stays asleep while what
## holds it (walls, the floor's friction) can still bear the new gravity, and wakes and
## rolls the step it cannot.

const BALL_R := 5.0
const HZ := 120.0


## A right-angled corner: a floor along y = 100 and a wall along x = 100, joined at
## (100, 100), with a ball of radius 5 resting in the inside corner.
func _corner_world() -> BallWorld:
	var w := BallWorld.new(TuningPresets.maze())
	w.shapes.add_wall(Vector2(0, 100), Vector2(100, 100), 5.0)
	w.shapes.add_wall(Vector2(100, 0), Vector2(100, 100), 5.0)
	return w


func _corner_spot() -> Vector2:
	return Vector2(100 - 5.0 - BALL_R, 100 - 5.0 - BALL_R)


func _steps(w: BallWorld, n: int, tilt := Vector2.INF, tilt_to := Vector2.INF) -> void:
	for k: int in n:
		if tilt.is_finite():
			# Sweep the tilt from `tilt` to `tilt_to`, one new gravity every step.
			MazeTilt.apply(w, tilt.lerp(tilt_to, float(k + 1) / n))
		w.step(1.0 / HZ)


func test_a_ball_in_a_corner_sleeps_through_a_tilt_that_keeps_it_there() -> void:
	var w := _corner_world()
	MazeTilt.apply(w, Vector2(10, 10))
	var id := w.spawn_ball(_corner_spot(), Vector2.ZERO, BALL_R)
	_steps(w, 60)
	assert_true(w.is_ball_asleep(id), "it settles in the corner")
	var p := w.get_ball_position(id)
	# Every step a new gravity, but always into the corner.
	_steps(w, 120, Vector2(10, 10), Vector2(2, 15))
	assert_true(w.is_ball_asleep(id), "still pressed into the corner: it sleeps on")
	assert_eq(w.get_ball_position(id), p)


func test_a_corner_sleeper_wakes_and_rolls_when_the_tilt_turns_out() -> void:
	var w := _corner_world()
	MazeTilt.apply(w, Vector2(10, 10))
	var id := w.spawn_ball(_corner_spot(), Vector2.ZERO, BALL_R)
	_steps(w, 60)
	assert_true(w.is_ball_asleep(id))
	# Tilt to the left: the wall at the right no longer holds it.
	MazeTilt.apply(w, Vector2(-10, 10))
	_steps(w, 1)
	assert_false(w.is_ball_asleep(id), "the step the tilt turns against it, it wakes")
	_steps(w, 30)
	assert_lt(w.get_ball_position(id).x, _corner_spot().x - 10.0, "and rolls along the floor")
	assert_almost_eq(w.get_ball_position(id).y, _corner_spot().y, 0.1, "on the floor")


func test_friction_holds_a_sleeper_on_a_gentle_slope_but_not_a_steep_one() -> void:
	var t := TuningPresets.maze()
	var w := BallWorld.new(t)
	var id := w.spawn_ball(Vector2(50, 50), Vector2.ZERO, BALL_R)
	_steps(w, 30)
	assert_true(w.is_ball_asleep(id), "level board: it sleeps")
	# Friction is μ·g·cos θ per axis; gravity g·sin θ; tan θ = μ is where it starts to roll.
	var gentle: float = rad_to_deg(atan(t.rolling_friction / t.tilt_gravity)) * 0.5
	_steps(w, 30, Vector2.ZERO, Vector2(gentle, 0))
	assert_true(w.is_ball_asleep(id), "below the friction angle it stays")
	assert_eq(w.get_ball_position(id), Vector2(50, 50))
	_steps(w, 30, Vector2(gentle, 0), Vector2(gentle * 4.0, 0))
	assert_false(w.is_ball_asleep(id), "past it, it wakes")
	assert_gt(w.get_ball_position(id).x, 50.0, "and rolls downhill")


func test_a_ball_pressing_on_a_sleeper_under_gravity_does_not_wake_it() -> void:
	var w := _corner_world()
	MazeTilt.apply(w, Vector2(10, 10))
	var first := w.spawn_ball(_corner_spot(), Vector2.ZERO, BALL_R)
	_steps(w, 60)
	assert_true(w.is_ball_asleep(first))
	# A second ball rolls up along the floor and comes to rest against the first.
	w.spawn_ball(_corner_spot() - Vector2(40, 0), Vector2.ZERO, BALL_R)
	_steps(w, 240, Vector2(10, 10), Vector2(12, 8))
	assert_true(w.is_ball_asleep(first), "the first ball sleeps on in its corner")
	assert_eq(w.get_ball_position(first), _corner_spot())


func test_a_ball_against_a_held_ball_settles_instead_of_bouncing() -> void:
	var w := _corner_world()
	MazeTilt.apply(w, Vector2(10, 10))
	var first := w.spawn_ball(_corner_spot(), Vector2.ZERO, BALL_R)
	var second := w.spawn_ball(_corner_spot() - Vector2(30, 0), Vector2.ZERO, BALL_R)
	_steps(w, 240)
	var gap: float = w.get_ball_position(first).x - w.get_ball_position(second).x
	assert_almost_eq(gap, 2.0 * BALL_R, 0.1, "the second lies against the first")
	assert_lt(w.get_ball_velocity(second).length(), w.tuning.rest_speed, "at rest")
	assert_true(w.is_ball_asleep(second), "and asleep")


func test_a_queue_in_a_corner_sleeps_through_the_tilt_and_leaves_together() -> void:
	var w := _corner_world()
	MazeTilt.apply(w, Vector2(10, 10))
	var first := w.spawn_ball(_corner_spot(), Vector2.ZERO, BALL_R)
	var second := w.spawn_ball(_corner_spot() - Vector2(2.0 * BALL_R, 0), Vector2.ZERO, BALL_R)
	_steps(w, 60)
	assert_true(w.is_ball_asleep(second), "the ball resting on the first sleeps too")
	var p := w.get_ball_position(second)
	_steps(w, 120, Vector2(10, 10), Vector2(14, 4))
	assert_true(w.is_ball_asleep(second), "it rides out a tilt that keeps it against the first")
	assert_eq(w.get_ball_position(second), p)
	# Tilt to the left: both roll off along the floor.
	MazeTilt.apply(w, Vector2(-10, 10))
	_steps(w, 1)
	assert_false(w.is_ball_asleep(second), "it wakes the step the tilt turns")
	_steps(w, 30)
	assert_lt(w.get_ball_position(second).x, p.x - 10.0, "and rolls away")
	assert_lt(w.get_ball_position(first).x, _corner_spot().x - 10.0, "and so does the first")
