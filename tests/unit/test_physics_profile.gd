extends GutTest
## BallWorld.profile_stages: per-stage times for the bench, and no effect on the results.


func _world() -> BallWorld:
	var w := BallWorld.new()
	w.shapes.set_ring(Vector2.ZERO, 200.0)
	for x: int in range(-150, 151, 30):
		w.shapes.add_pin(Vector2(x, 0.0), 2.0)
	for k: int in 100:
		w.spawn_ball(Vector2(-120.0 + 2.4 * k, -100.0 + (k % 7) * 11.0), Vector2.ZERO, 5.0)
	w.build_grid()
	return w


func test_stage_times_cover_every_stage_while_profiling() -> void:
	var w := _world()
	w.profile_stages = true
	w.profile_cpu_time = true
	for _s: int in 30:
		w.step(1.0 / 120.0)
	var t: Dictionary = w.stage_times()
	for key: String in ["integrate", "broad_phase", "ball_solve", "motion", "events"]:
		assert_true(t.has(key), "stage %s reported" % key)
	assert_gt(float(t["motion"]), 0.0, "moving 100 balls takes time")
	var sum := 0.0
	for key: String in t:
		if key != "total":
			sum += float(t[key])
	assert_almost_eq(float(t["total"]), sum, 0.001, "total is the sum of the stages")


func test_stage_times_are_zero_when_not_profiling() -> void:
	var w := _world()
	for _s: int in 10:
		w.step(1.0 / 120.0)
	assert_eq(float(w.stage_times()["total"]), 0.0)


func test_profiling_does_not_change_the_state() -> void:
	var plain := _world()
	var timed := _world()
	timed.profile_stages = true
	for _s: int in 60:
		plain.step(1.0 / 120.0)
		timed.step(1.0 / 120.0)
	assert_eq(timed.state_hash(), plain.state_hash())
