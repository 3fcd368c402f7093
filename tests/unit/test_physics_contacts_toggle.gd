extends GutTest
## Ball contacts switched off and back on: without contacts the motion stage skips the
## broad-phase keys, so the broad phase must bin every ball again when contacts return
## and find every touching pair as if they had been on throughout.

const STEPS := 240
const DT := 1.0 / 120.0


## Two balls in a ring, flying head-on at each other (they meet after about 110 steps).
func _head_on_world() -> BallWorld:
	var w := BallWorld.new(TuningPresets.pachinko())
	w.threads = 1
	w.gravity = Vector2.ZERO
	w.shapes.set_ring(Vector2.ZERO, 220.0)
	w.build_grid()
	w.spawn_ball(Vector2(-100, 0), Vector2(100, 0), 4.0)
	w.spawn_ball(Vector2(100, 0), Vector2(-100, 0), 4.0)
	return w


## Steps `w` STEPS times; ball contacts are on for the first 10 steps and again from step
## `contacts_from` (never again when -1).
func _run(w: BallWorld, contacts_from: int) -> void:
	for s: int in STEPS:
		w.ball_contacts = s < 10 or (contacts_from >= 0 and s >= contacts_from)
		w.step(DT)


func test_contacts_back_on_match_contacts_on_throughout() -> void:
	var always := _head_on_world()
	_run(always, 0)
	var toggled := _head_on_world()
	_run(toggled, 60)
	assert_eq(toggled.state_hash(), always.state_hash(), "same world once contacts are back")
	assert_lt(toggled.get_velocities()[0].x, 0.0, "the left ball bounced back")


func test_contacts_off_balls_pass_through() -> void:
	var always := _head_on_world()
	_run(always, 0)
	var never := _head_on_world()
	_run(never, -1)
	assert_ne(never.state_hash(), always.state_hash(), "without contacts the run differs")
	assert_gt(never.get_velocities()[0].x, 0.0, "the left ball flew on through")
