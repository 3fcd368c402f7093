extends GutTest
## The analysis split over worker processes (AnalysisWorkerPool): the same counts as one
## thread in this process, also when a worker dies or hangs on purpose (the test hook
## AnalysisQueueWorker.FAULT_ENV, which the workers inherit) and its chunks are run again;
## cancel leaves no worker process behind; a run of some chunks only (only_chunks) counts
## exactly those chunks. This process fires ranges beside its workers (work_here) with the
## same counts; the fault tests turn that off, so the workers, not this process, meet the
## faults.

const SHOTS := 1000
## A pool run that takes longer than this is stuck (a range lost): the test fails, ms.
const DEADLINE_MS := 180000


func after_each() -> void:
	OS.unset_environment(AnalysisQueueWorker.FAULT_ENV)


func _classic() -> BoardLevel:
	return BoardLoader.load_board("res://levels/pachinko/classic.board").level


func _one_thread(plan: AnalysisPlan) -> AnalysisTally:
	var alone := AnalysisPlan.create(plan.level, plan.shots, plan.rng_seed)
	alone.threads = 1
	return PachinkoAnalysis.new(alone).run()


func _assert_same_counts(there: AnalysisTally, here: AnalysisTally, plan: AnalysisPlan) -> void:
	assert_not_null(there, "the workers' counts came back")
	if there == null:
		return
	var a := AnalysisReport.build(plan, here, 1.0)
	var b := AnalysisReport.build(plan, there, 1.0)
	assert_eq(JSON.stringify(b), JSON.stringify(a), "the same report")
	assert_eq(there.density, here.density, "the same heat map")
	assert_eq(there.ball_steps, here.ball_steps, "the same ball-steps")


# The pool's bonus-open counts are the ones one thread gives with the bonus pockets open.
func _assert_same_open_counts(pool: AnalysisWorkerPool, plan: AnalysisPlan) -> void:
	var open_plan := plan.with_bonus_open()
	open_plan.threads = 1
	var open_here := PachinkoAnalysis.new(open_plan).run()
	var open_there := pool.open_tally()
	assert_not_null(open_there, "the bonus-open counts came back")
	if open_there != null:
		assert_eq(open_there.band_pocket_hits, open_here.band_pocket_hits)
		assert_eq(open_there.ball_steps, open_here.ball_steps)


# True when process `pid` is gone (on systems with /proc; elsewhere: assumed).
func _gone(pid: int) -> bool:
	if not DirAccess.dir_exists_absolute("/proc/self"):
		return true
	return not DirAccess.dir_exists_absolute("/proc/%d" % pid)


func _assert_all_gone(pool: AnalysisWorkerPool, started: PackedInt32Array) -> void:
	for pid in started:
		assert_true(_gone(pid), "worker process %d is gone" % pid)
	assert_eq(pool.process_ids().count(-1), pool.process_ids().size(), "none is left running")


# Polls `pool` (started, or started here) until it is done; a run past DEADLINE_MS is
# cancelled and fails the test, so a lost range cannot hang the suite. Its counts, or null.
func _finish(pool: AnalysisWorkerPool) -> AnalysisTally:
	if pool.phase == PachinkoAnalysis.Phase.IDLE and not pool.start():
		return null
	var started := Time.get_ticks_msec()
	while not pool.poll():
		if Time.get_ticks_msec() - started > DEADLINE_MS:
			pool.cancel()
			fail_test("the run did not finish in %d s" % (DEADLINE_MS / 1000))
			return null
		OS.delay_msec(AnalysisWorkerPool.POLL_MS)
	return pool.tally()


func _pool(workers: int, here := false) -> AnalysisWorkerPool:
	var plan := AnalysisPlan.create(_classic(), SHOTS, 1)
	plan.threads = 2
	var pool := AnalysisWorkerPool.new(plan)
	pool.workers = workers
	pool.work_here = here
	return pool


func test_this_process_fires_ranges_beside_its_workers() -> void:
	var pool := _pool(1, true)
	var there := _finish(pool)
	assert_eq(pool.phase, PachinkoAnalysis.Phase.DONE)
	assert_eq(pool.incidents, PackedStringArray(), "nothing failed")
	# The first range is taken here before any worker's engine has started.
	assert_gt(pool.ranges_here(), 0, "this process fired some ranges itself")
	_assert_same_counts(there, _one_thread(pool.plan), pool.plan)


func test_ranges_fired_here_match_with_the_bonus_open_counts() -> void:
	var fever := BoardLoader.load_board("res://levels/pachinko/fever.board").level
	var plan := AnalysisPlan.create(fever, 500, 3)
	var pool := AnalysisWorkerPool.new(plan)
	pool.workers = 1
	pool.with_open = true
	var there := _finish(pool)
	assert_gt(pool.ranges_here(), 0, "this process fired some ranges itself")
	_assert_same_counts(there, _one_thread(plan), plan)
	_assert_same_open_counts(pool, plan)


func test_a_dying_worker_beside_this_process_loses_no_range() -> void:
	OS.set_environment(AnalysisQueueWorker.FAULT_ENV, "die:0")
	var plan := AnalysisPlan.create(_classic(), 3000, 1)
	var pool := AnalysisWorkerPool.new(plan)
	pool.workers = 1
	var there := _finish(pool)
	assert_eq(pool.phase, PachinkoAnalysis.Phase.DONE)
	_assert_same_counts(there, _one_thread(plan), plan)


func test_cancel_stops_the_ranges_fired_here() -> void:
	var plan := AnalysisPlan.create(_classic(), 10000, 1)
	var pool := AnalysisWorkerPool.new(plan)
	pool.workers = 1
	assert_true(pool.start())
	var started := pool.process_ids().duplicate()
	var waited := 0
	while not pool.firing_here() and waited < 5000:
		pool.poll()
		OS.delay_msec(5)
		waited += 5
	assert_true(pool.firing_here(), "this process took a range")
	pool.cancel()
	assert_false(pool.firing_here(), "no range runs here once cancelled")
	assert_true(pool.poll(), "done once cancelled")
	assert_eq(pool.phase, PachinkoAnalysis.Phase.CANCELLED)
	_assert_all_gone(pool, started)


func test_two_workers_count_what_one_thread_counts() -> void:
	var pool := _pool(2)
	var there := _finish(pool)
	assert_eq(pool.failure, "", "the workers started")
	assert_eq(pool.phase, PachinkoAnalysis.Phase.DONE)
	assert_eq(pool.incidents, PackedStringArray(), "no worker failed")
	_assert_same_counts(there, _one_thread(pool.plan), pool.plan)
	assert_eq(pool.progress(), 1.0)
	assert_eq(pool.process_ids().size(), 2, "two workers ran")


func test_the_bonus_open_counts_match_too() -> void:
	var fever := BoardLoader.load_board("res://levels/pachinko/fever.board").level
	var plan := AnalysisPlan.create(fever, 500, 3)
	var pool := AnalysisWorkerPool.new(plan)
	pool.workers = 2
	pool.with_open = true
	var there := _finish(pool)
	_assert_same_counts(there, _one_thread(plan), plan)
	_assert_same_open_counts(pool, plan)


func test_a_dying_worker_is_reported_and_its_chunks_run_again() -> void:
	OS.set_environment(AnalysisQueueWorker.FAULT_ENV, "die:0")
	var pool := _pool(2)
	var there := _finish(pool)
	assert_eq(pool.phase, PachinkoAnalysis.Phase.DONE)
	assert_eq(pool.incidents.size(), 1, "one incident: %s" % [pool.incidents])
	if pool.incidents.size() == 1:
		assert_string_contains(pool.incidents[0], "worker 0")
		assert_string_contains(pool.incidents[0], "stopped")
		assert_string_contains(pool.incidents[0], "without the counts of chunks ")
	_assert_same_counts(there, _one_thread(pool.plan), pool.plan)


func test_a_hung_worker_is_killed_and_its_chunks_run_again() -> void:
	OS.set_environment(AnalysisQueueWorker.FAULT_ENV, "hang:1")
	var pool := _pool(2)
	pool.hang_seconds = 2.0
	assert_true(pool.start())
	var started := pool.process_ids().duplicate()
	_finish(pool)
	assert_eq(pool.phase, PachinkoAnalysis.Phase.DONE)
	assert_eq(pool.incidents.size(), 1, "one incident: %s" % [pool.incidents])
	if pool.incidents.size() == 1:
		assert_string_contains(pool.incidents[0], "worker 1 (process %d)" % started[1])
		assert_string_contains(pool.incidents[0], "no progress")
	assert_true(_gone(started[1]), "the hung worker was killed")
	_assert_same_counts(pool.tally(), _one_thread(pool.plan), pool.plan)


func test_when_every_worker_dies_the_rest_runs_here() -> void:
	OS.set_environment(AnalysisQueueWorker.FAULT_ENV, "die:0")
	var pool := _pool(1)
	var there := _finish(pool)
	assert_eq(pool.phase, PachinkoAnalysis.Phase.DONE)
	assert_eq(pool.incidents.size(), 2, "the worker died, the rest ran here: %s" % [pool.incidents])
	_assert_same_counts(there, _one_thread(pool.plan), pool.plan)


func test_cancel_leaves_no_worker_running() -> void:
	var plan := AnalysisPlan.create(_classic(), 10000, 1)
	var pool := AnalysisWorkerPool.new(plan)
	pool.workers = 2
	assert_true(pool.start())
	var started := pool.process_ids().duplicate()
	OS.delay_msec(500)
	assert_false(pool.poll(), "still running")
	pool.cancel()
	assert_true(pool.poll(), "done once cancelled")
	assert_eq(pool.phase, PachinkoAnalysis.Phase.CANCELLED)
	_assert_all_gone(pool, started)


func test_a_finished_run_leaves_no_worker_running() -> void:
	var pool := AnalysisWorkerPool.new(AnalysisPlan.create(_classic(), 250, 1))
	pool.workers = 2
	assert_true(pool.start())
	var started := pool.process_ids().duplicate()
	_finish(pool)
	assert_eq(started.size(), 1, "one range: one worker")
	_assert_all_gone(pool, started)


func test_some_chunks_count_exactly_those_chunks() -> void:
	var plan := AnalysisPlan.create(_classic(), 750, 5)
	plan.threads = 1
	var whole := PachinkoAnalysis.new(plan).run()
	var first := PachinkoAnalysis.new(plan)
	first.only_chunks = PackedInt32Array([2, 0])
	var merged := first.run()
	assert_eq(merged.total_shots(), 500, "two chunks' shots")
	# The rest climbs only the levels the first run did not (into the first run's table).
	var rest := PachinkoAnalysis.new(plan)
	rest.only_chunks = PackedInt32Array([1])
	rest.reuse_climbs(first.climb_table())
	merged.merge(rest.run())
	var a := AnalysisReport.build(plan, whole, 1.0)
	assert_eq(JSON.stringify(AnalysisReport.build(plan, merged, 1.0)), JSON.stringify(a))
	assert_eq(merged.ball_steps, whole.ball_steps)


func test_a_plan_the_workers_cannot_run_fails_with_a_reason() -> void:
	var pool := _pool(0)
	assert_false(pool.start())
	assert_string_contains(pool.failure, "worker")
	var open_pool := AnalysisWorkerPool.new(
		AnalysisPlan.create(_classic(), 100, 1).with_bonus_open()
	)
	assert_false(open_pool.start())
	assert_string_contains(open_pool.failure, "with_open")


func test_workers_exit_when_their_parent_is_stopped() -> void:
	if not DirAccess.dir_exists_absolute("/proc/self"):
		pass_test("needs /proc to find the workers")
		return
	var out := ProjectSettings.globalize_path("user://test_worker_pool_out")
	var args := PackedStringArray(
		[
			"--headless",
			"--quiet",
			"--path",
			ProjectSettings.globalize_path("res://"),
			"--",
			"--analyze=pachinko",
			"--board=classic",
			"--shots=10000",
			"--workers=2",
			"--out=%s" % out,
		]
	)
	var parent := OS.create_process(OS.get_executable_path(), args)
	assert_gt(parent, 0, "the command started")
	var workers := _workers_of(parent)
	var started := Time.get_ticks_msec()
	while workers.size() < 2 and Time.get_ticks_msec() - started < 30000:
		OS.delay_msec(200)
		workers = _workers_of(parent)
	assert_eq(workers.size(), 2, "its two workers run")
	OS.kill(parent)
	started = Time.get_ticks_msec()
	while not _all_stopped(workers) and Time.get_ticks_msec() - started < 10000:
		OS.delay_msec(100)
	assert_true(_all_stopped(workers), "every worker of the stopped command exited")


# The worker processes of the analysis process `parent` (their queue folder is named after
# it), found by their command lines in /proc.
func _workers_of(parent: int) -> PackedInt32Array:
	var found := PackedInt32Array()
	for entry in DirAccess.get_directories_at("/proc"):
		if not entry.is_valid_int():
			continue
		var file := FileAccess.open("/proc/%s/cmdline" % entry, FileAccess.READ)
		if file == null:
			continue
		var line := file.get_buffer(8192)
		for i in line.size():
			if line[i] == 0:
				line[i] = 32
		if line.get_string_from_utf8().contains("/%d_" % parent):
			if line.get_string_from_utf8().contains("--queue="):
				found.append(int(entry))
	return found


# True when none of `pids` runs (gone, or a zombie no one reaped yet).
func _all_stopped(pids: PackedInt32Array) -> bool:
	for pid in pids:
		var file := FileAccess.open("/proc/%d/stat" % pid, FileAccess.READ)
		if file == null:
			continue
		var stat := file.get_buffer(512).get_string_from_utf8()
		var state := stat.get_slice(") ", 1).left(1)
		if state != "Z" and state != "X" and not state.is_empty():
			return false
	return true


func test_the_queue_of_a_run_whose_process_is_gone_is_removed() -> void:
	if not DirAccess.dir_exists_absolute("/proc/self"):
		pass_test("needs /proc to tell which processes live")
		return
	var root := ProjectSettings.globalize_path(AnalysisWorker.FOLDER)
	var dead := 4190000
	while DirAccess.dir_exists_absolute("/proc/%d" % dead):
		dead += 1
	var stale := root.path_join("%d_1.queue" % dead)
	var mine := root.path_join("%d_1.queue" % OS.get_process_id())
	for folder in [stale, mine]:
		DirAccess.make_dir_recursive_absolute(folder)
		FileAccess.open(folder.path_join("todo_r00000-00000"), FileAccess.WRITE).close()
	AnalysisQueueFolder.remove_stale(root)
	assert_false(DirAccess.dir_exists_absolute(stale), "the dead run's queue is gone")
	assert_true(DirAccess.dir_exists_absolute(mine), "a live run's queue stays")
	DirAccess.remove_absolute(mine.path_join("todo_r00000-00000"))
	DirAccess.remove_absolute(mine)
