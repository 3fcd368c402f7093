extends GutTest
## LaneCrew: BallLanes' own worker threads. Every lane of every hand-off runs exactly once
## and is finished when run() returns, whoever took it; only the workers a hand-off may use
## take lanes (a stage keeps one working state per worker number); freeing the lanes joins
## the threads.


func test_every_lane_of_many_hand_offs_runs_once_and_is_done_on_return() -> void:
	var crew := LaneCrew.new()
	var rng := RandomNumberGenerator.new()
	rng.seed = 5
	var problems: Array[String] = []
	for hand_off: int in 300:
		var helpers: int = rng.randi_range(1, 3)
		var lanes: int = rng.randi_range(1, 12)
		var items: int = lanes * 20
		var bounds := BallLanes.tapered_bounds(items, lanes)
		var seen := PackedInt32Array()
		seen.resize(items)
		seen.fill(0)
		var workers := PackedInt32Array()
		workers.resize(lanes)
		workers.fill(-1)
		crew.run(
			func(worker: int, lane: int, from: int, to: int) -> void:
				workers[lane] = worker
				for i: int in range(from, to):
					seen[i] += 1,
			bounds,
			helpers,
			true
		)
		if seen.count(1) != items:
			problems.append(
				"hand-off %d: %d of %d items ran once" % [hand_off, seen.count(1), items]
			)
		for lane: int in lanes:
			if workers[lane] < 0 or workers[lane] > helpers:
				problems.append(
					"hand-off %d: lane %d on worker %d" % [hand_off, lane, workers[lane]]
				)
	crew.stop()
	assert_eq(
		problems, [] as Array[String], "every lane once, done on return, on a worker it may use"
	)


func test_hand_offs_to_watching_and_to_sleeping_workers_each_run_every_lane_once() -> void:
	# Back to back, a worker is still watching for the next hand-off; after a pause longer
	# than its watch it has gone to sleep and needs a post. Both must run every lane once.
	var crew := LaneCrew.new()
	var problems: Array[String] = []
	for hand_off: int in 80:
		if hand_off % 4 == 3:
			OS.delay_msec(3)
		var seen := PackedInt32Array()
		seen.resize(60)
		seen.fill(0)
		crew.run(
			func(_worker: int, _lane: int, from: int, to: int) -> void:
				OS.delay_usec(50)
				for i: int in range(from, to):
					seen[i] += 1,
			BallLanes.tapered_bounds(60, 6),
			2,
			true
		)
		if seen.count(1) != 60:
			problems.append("hand-off %d: %d of 60 items ran once" % [hand_off, seen.count(1)])
	var started: int = crew.started
	crew.stop()
	assert_eq(problems, [] as Array[String], "every lane once, whether workers watched or slept")
	assert_eq(started, 2, "two helpers started")
	assert_eq(crew.started, 0, "stop() joined workers that were watching or asleep")


func test_a_job_without_worker_numbers_gets_lane_and_range() -> void:
	var crew := LaneCrew.new()
	var seen := PackedInt32Array()
	seen.resize(100)
	seen.fill(0)
	crew.run(
		func(_lane: int, from: int, to: int) -> void:
			for i: int in range(from, to):
				seen[i] += 1,
		BallLanes.tapered_bounds(100, 5),
		1,
		false
	)
	crew.stop()
	assert_eq(seen.count(1), 100)


func test_freeing_the_lanes_joins_their_workers() -> void:
	var lanes := BallLanes.new()
	lanes.threads = 2
	lanes.run(func(_lane: int, _from: int, _to: int) -> void: pass, 1000)
	var crew := lanes.crew()
	assert_eq(crew.started, 1, "two threads: one worker besides the calling thread")
	lanes = null
	assert_eq(crew.started, 0, "the worker was stopped and joined with its lanes object")


func test_tapered_lanes_cover_every_item_once_each_no_larger_than_the_one_before() -> void:
	var problems: Array[String] = []
	for lanes: int in range(1, 17):
		for count: int in [0, 1, 7, 48, 100, 1000, 3001]:
			var bounds: PackedInt32Array = BallLanes.tapered_bounds(count, lanes)
			var what := "%d items in %d lanes: %s" % [count, lanes, bounds]
			if bounds.size() != lanes + 1 or bounds[0] != 0 or bounds[lanes] != count:
				problems.append(what + " (ends)")
				continue
			for k: int in lanes:
				var size: int = bounds[k + 1] - bounds[k]
				if size < 0 or (k > 0 and size > bounds[k] - bounds[k - 1] + 1):
					problems.append(what + " (lane %d)" % k)
	assert_eq(problems, [] as Array[String], "whole, ordered, tapering lanes")
	var thousand: PackedInt32Array = BallLanes.tapered_bounds(1000, 8)
	assert_gt(
		thousand[1] - thousand[0],
		3 * (thousand[8] - thousand[7]) - 10,
		"last lane ~ a third of the first"
	)
