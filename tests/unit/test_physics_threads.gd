extends GutTest
## Thread-count independence: the per-ball stages run in lanes on worker threads, and 1, 2
## and 4 threads must give bit-identical worlds and the same events in the same order.


## A ring board with pins, a wall and a gutter, crowded enough for several lanes.
func _pachinko_world(threads: int) -> BallWorld:
	var w := BallWorld.new(TuningPresets.pachinko())
	w.threads = threads
	w.shapes.set_ring(Vector2.ZERO, 220.0)
	w.shapes.set_drain_arc(60.0, 120.0, 3, w.tuning.drain_slide_time)
	w.shapes.add_wall(Vector2(-150, 60), Vector2(-20, 100), 3.0)
	var rng := RandomNumberGenerator.new()
	rng.seed = 7
	for _i: int in 120:
		w.shapes.add_pin(Vector2(rng.randf_range(-150, 150), rng.randf_range(-100, 100)), 1.5)
	w.shapes.add_pin(Vector2(0, 140), 1.5, 3, true)
	w.build_grid()
	for _i: int in 400:
		var p := Vector2(rng.randf_range(-120, 120), rng.randf_range(-200, -110))
		w.spawn_ball(p, Vector2(rng.randf_range(-200, 200), 0), 4.0)
	return w


## Walls only, tilted, with friction and sleep: the maze's path through the stages.
func _maze_world(threads: int) -> BallWorld:
	var t := TuningPresets.maze()
	var w := BallWorld.new(t)
	w.threads = threads
	for k: int in 10:
		w.shapes.add_wall(Vector2(k * 40, 0), Vector2(k * 40 + 20, 300), 4.0)
	w.shapes.add_wall(Vector2(-10, 320), Vector2(420, 320), 4.0)
	w.shapes.add_goal(Vector2(200, 300), 30.0)
	var rng := RandomNumberGenerator.new()
	rng.seed = 11
	for _i: int in 300:
		w.spawn_ball(Vector2(rng.randf_range(0, 400), rng.randf_range(0, 280)), Vector2.ZERO, 4.0)
	w.gravity = Vector2(300, 900)
	w.rolling_friction = Vector2(40, 40)
	return w


## Runs `steps` steps and returns [state hash, event log].
func _run(w: BallWorld, steps: int) -> Array:
	var log: Array = []
	w.pin_hit.connect(func(b: int, p: int, s: float) -> void: log.append(["pin", b, p, s]))
	w.wall_hit.connect(func(b: int, k: int, s: float) -> void: log.append(["wall", b, k, s]))
	w.ring_hit.connect(func(b: int, s: float) -> void: log.append(["ring", b, s]))
	w.ball_captured.connect(func(b: int, p: int) -> void: log.append(["pocket", b, p]))
	w.ball_drained.connect(func(b: int) -> void: log.append(["drain", b]))
	w.ball_reached_goal.connect(func(b: int, g: int) -> void: log.append(["goal", b, g]))
	for _i: int in steps:
		w.step(1.0 / 120.0)
	return [w.state_hash(), log]


func test_pachinko_world_is_bit_identical_for_1_2_and_4_threads() -> void:
	var one: Array = _run(_pachinko_world(1), 240)
	assert_gt((one[1] as Array).size(), 100, "the balls did hit things")
	for threads: int in [2, 4]:
		var many: Array = _run(_pachinko_world(threads), 240)
		assert_eq(many[0], one[0], "same state with %d threads" % threads)
		assert_eq(many[1], one[1], "same events in the same order with %d threads" % threads)


func test_maze_world_is_bit_identical_for_1_2_and_4_threads() -> void:
	var one: Array = _run(_maze_world(1), 240)
	for threads: int in [2, 4]:
		var many: Array = _run(_maze_world(threads), 240)
		assert_eq(many[0], one[0], "same state with %d threads" % threads)
		assert_eq(many[1], one[1], "same events with %d threads" % threads)


func test_path_recording_is_the_same_for_any_thread_count() -> void:
	var paths: Array = []
	for threads: int in [1, 3]:
		var w := _pachinko_world(threads)
		w.set_path_recording(true)
		for _i: int in 20:
			w.step(1.0 / 60.0)
		paths.append(w.take_step_paths())
	assert_gt((paths[0]["points"] as PackedVector2Array).size(), 0, "fast balls substepped")
	assert_eq(paths[1]["slots"], paths[0]["slots"])
	assert_eq(paths[1]["points"], paths[0]["points"])


## A pile in a bowl: hundreds of touching pairs over many stripes, so the ball-ball solve
## runs on the threads (more pairs than BallPairs.PAIRS_WORTH_THREADS of each parity).
func _pile_world(threads: int) -> BallWorld:
	var w := BallWorld.new(TuningPresets.pachinko())
	w.threads = threads
	w.shapes.set_ring(Vector2.ZERO, 160.0)
	var rng := RandomNumberGenerator.new()
	rng.seed = 5
	for _i: int in 900:
		var p := Vector2(rng.randf_range(-120, 120), rng.randf_range(-40, 140))
		w.spawn_ball(p, Vector2(rng.randf_range(-50, 50), 0), 4.0)
	return w


func test_a_pile_solved_on_the_threads_is_bit_identical_for_1_2_and_4_threads() -> void:
	var worlds: Array[BallWorld] = [_pile_world(1), _pile_world(2), _pile_world(4)]
	var most_pairs := 0
	for _s: int in 90:
		for w: BallWorld in worlds:
			w.step(1.0 / 240.0)
		var pairs := 0
		for used: int in worlds[2]._pairs.stripe_used:
			pairs += used >> 1
		most_pairs = maxi(most_pairs, pairs)
	assert_gt(most_pairs, 4 * BallPairs.PAIRS_WORTH_THREADS, "the pile has pairs for the threads")
	assert_eq(worlds[1].state_hash(), worlds[0].state_hash(), "2 threads")
	assert_eq(worlds[2].state_hash(), worlds[0].state_hash(), "4 threads")


func test_lanes_cover_every_ball_once_on_several_threads() -> void:
	var lanes := BallLanes.new()
	lanes.threads = 4
	var seen := PackedInt32Array()
	seen.resize(1000)
	seen.fill(0)
	var used: int = lanes.run(
		func(_lane: int, from: int, to: int) -> void:
			for i: int in range(from, to):
				seen[i] += 1,
		1000
	)
	assert_gt(used, 4, "a big stage is split into several lanes per thread")
	assert_lte(used, 4 * BallLanes.LANES_PER_THREAD)
	assert_eq(seen.count(1), 1000, "each ball in exactly one lane")


func test_a_small_stage_stays_on_the_calling_thread() -> void:
	var lanes := BallLanes.new()
	lanes.threads = 4
	assert_eq(lanes.lanes_for(BallLanes.MIN_BALLS_PER_LANE - 1), 1)
	assert_eq(lanes.lanes_for(BallLanes.MIN_BALLS_PER_LANE * 2), 2)
	lanes.threads = 1
	assert_eq(lanes.lanes_for(100000), 1, "one thread: one lane, no pool")


func test_thread_count_below_one_means_one() -> void:
	var w := BallWorld.new()
	w.threads = 0
	assert_eq(w.threads, 1)


## Regression: get_positions() hands out a duplicate that shares the world's buffer until
## one side writes. Both lanes then copied the array at once on their first writes, and the
## bench crashed (out-of-bounds reads, then a corrupted heap). The world now takes its own
## buffers before the lanes run.
func test_reading_state_between_steps_is_safe_on_several_threads() -> void:
	var one := _pachinko_world(1)
	var many := _pachinko_world(2)
	var held: Array[PackedVector2Array] = []
	for _i: int in 60:
		one.step(1.0 / 120.0)
		var before := many.get_positions()
		var copy := before.duplicate()
		many.get_velocities()
		many.step(1.0 / 120.0)
		held.append(before)
		assert_eq(before, copy, "a copy handed out does not change with the world")
	assert_eq(many.state_hash(), one.state_hash())
	assert_eq(held.size(), 60)


## The store makes its buffers its own only after something was handed out (a step with
## nothing handed out skips it): handing out on some steps only must be as safe.
func test_reading_state_on_some_steps_only_is_safe_on_several_threads() -> void:
	var one := _pachinko_world(1)
	var many := _pachinko_world(2)
	for i: int in 60:
		one.step(1.0 / 120.0)
		var before := PackedVector2Array()
		var copy := PackedVector2Array()
		if i % 5 == 0:
			before = many.get_positions()
			copy = before.duplicate()
		many.step(1.0 / 120.0)
		assert_eq(before, copy, "a copy handed out on step %d does not change" % i)
	assert_eq(many.state_hash(), one.state_hash())


func test_worlds_stepped_inside_pool_tasks_do_not_wait_on_the_pool() -> void:
	var worlds: Array[BallWorld] = [_pachinko_world(2), _pachinko_world(2)]
	var task: int = WorkerThreadPool.add_group_task(
		func(k: int) -> void:
			for _i: int in 30:
				worlds[k].step(1.0 / 120.0),
		2,
		2,
		true
	)
	WorkerThreadPool.wait_for_group_task_completion(task)
	var here := _pachinko_world(2)
	for _i: int in 30:
		here.step(1.0 / 120.0)
	assert_eq(worlds[0].state_hash(), here.state_hash(), "same state inside a pool task")
	assert_eq(worlds[1].state_hash(), here.state_hash())
