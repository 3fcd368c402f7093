extends GutTest
## BallWorld.profile_stages: per-stage times for the bench, and no effect on the results
## or on the schedule of stages a step runs.


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
	# Wall time and the thread's CPU time alike. Only the wall clock counts microseconds
	# everywhere: the CPU time some kernels keep per thread moves in scheduler ticks (4-10 ms),
	# more than these 30 steps take, so a stage may read 0 there and only the wall clock is
	# held to "takes time".
	for cpu: bool in [false, true]:
		var w := _world()
		w.threads = 1
		w.profile_stages = true
		w.profile_cpu_time = cpu
		for _s: int in 30:
			w.step(1.0 / 120.0)
		var t: Dictionary = w.stage_times()
		for key: String in ["integrate", "find_and_solve_even", "solve_odd", "motion", "events"]:
			assert_true(t.has(key), "stage %s reported (CPU time: %s)" % [key, cpu])
		if not cpu:
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


func test_profiling_does_not_change_the_state_or_the_schedule() -> void:
	var plain := _world()
	var timed := _world()
	timed.profile_stages = true
	plain.threads = 2
	timed.threads = 2
	plain._clock.recording = true
	timed._clock.recording = true
	for _s: int in 60:
		plain.step(1.0 / 120.0)
		timed.step(1.0 / 120.0)
	assert_eq(timed.state_hash(), plain.state_hash())
	assert_eq(timed._clock.laps.size(), 60 * StageClock.NAMES.size(), "every stage, every step")
	assert_eq(timed._clock.laps, plain._clock.laps, "the profiler times the schedule play runs")


func test_without_ball_contacts_the_schedule_keeps_its_stages() -> void:
	var w := _world()
	w.ball_contacts = false
	w._clock.recording = true
	w.step(1.0 / 120.0)
	assert_eq(w._clock.laps, PackedInt32Array([0, 1, 2, 3, 4]))
