extends GutTest
## BoardListLoading: board files load on worker threads and land one by one; a loading that
## says it is no longer busy has joined every thread it started, so dropping it never
## destroys a running or unjoined thread (Godot reports "Thread destroyed without
## wait_to_finish", and the level select could drop a loading between a thread's last
## result and its end).

const KIND := BoardLevel.Kind.MAZE


func _jobs(count: int) -> Array[Dictionary]:
	var jobs: Array[Dictionary] = []
	for i in count:
		jobs.append({"path": "res://levels/maze/%d.board" % i, "kind": KIND, "root": "res://"})
	return jobs


func _quick_load(path: String, _kind: int, _root: String) -> BoardLoadResult:
	var result := BoardLoadResult.new()
	result.path = path
	return result


func _wait_for_threads_to_end(loading: BoardListLoading) -> void:
	var started := Time.get_ticks_msec()
	while Time.get_ticks_msec() - started < 5000:
		if loading._threads.all(func(thread: Thread) -> bool: return not thread.is_alive()):
			return
		OS.delay_msec(2)


func test_every_file_lands_once_and_the_threads_are_joined() -> void:
	var loading := BoardListLoading.new(_jobs(5), _quick_load)
	var paths: Array[String] = []
	var started := Time.get_ticks_msec()
	while loading.is_busy() and Time.get_ticks_msec() - started < 5000:
		for done in loading.take_finished():
			paths.append(str(done["path"]))
		OS.delay_msec(2)
	paths.sort()
	assert_eq(paths.size(), 5, "every file once")
	assert_eq(paths[0], "res://levels/maze/0.board")
	assert_eq(loading._threads.size(), 0, "no thread left unjoined")


func test_not_busy_means_joined_even_when_the_results_were_taken_before_the_threads_ended() -> void:
	var loading := BoardListLoading.new(_jobs(2), _quick_load)
	_wait_for_threads_to_end(loading)
	# A frame took the results while the threads were still alive (so it joined none of them),
	# then the threads ended: the next is_busy() must join them before it says "done".
	loading._mutex.lock()
	var taken := loading._finished.size()
	loading._finished.clear()
	loading._mutex.unlock()
	assert_eq(taken, 2)
	assert_false(loading.is_busy())
	assert_eq(loading._threads.size(), 0, "is_busy() joined the ended threads")


func _slow_load(path: String, kind: int, root: String) -> BoardLoadResult:
	OS.delay_msec(200)
	return _quick_load(path, kind, root)


func test_quitting_waits_for_every_cancelled_thread() -> void:
	var loading := BoardListLoading.new(_jobs(6), _slow_load)
	OS.delay_msec(20)  # both workers are inside a slow file now
	loading.cancel()
	assert_false(loading._threads.is_empty(), "cancel alone does not wait for a busy thread")
	BoardListLoading.wait_for_cancelled()
	assert_true(loading._threads.is_empty(), "every thread was joined")
	assert_false(loading.is_busy())
	assert_eq(BoardListLoading._cancelled.size(), 0, "nothing is left to join at exit")


func test_one_worker_keeps_the_jobs_in_order() -> void:
	var loading := BoardListLoading.new(_jobs(6), _quick_load, 1)
	var paths: Array[String] = []
	while loading.is_busy():
		for done in loading.take_finished():
			paths.append(str(done["path"]))
		OS.delay_msec(2)
	var expected: Array[String] = []
	for job in _jobs(6):
		expected.append(str(job["path"]))
	assert_eq(paths, expected)
