class_name BoardListLoading
extends RefCounted
## Loads a list of board files off the main thread, so a screen listing them keeps drawing and
## taking input however long one file takes. A few worker threads take files from a queue;
## the screen polls `take_finished()` each frame and fills in each file's card as it lands.
## Nothing here touches the scene tree.
##
## A screen that goes away calls `cancel()`: files not started are dropped, and the threads
## still busy with a file finish it in the background and are joined later (`reap_finished`),
## so leaving never waits for a slow file.

## Worker threads per loading (files load in parallel; one slow file never holds the rest).
const WORKERS := 2

## Loadings cancelled while a thread was still busy; joined once their threads end.
static var _cancelled: Array[BoardListLoading] = []

var _load: Callable
var _queue: Array[Dictionary] = []
var _finished: Array[Dictionary] = []
var _mutex := Mutex.new()
var _threads: Array[Thread] = []
var _stopping := false


## `jobs` are dictionaries with "path", "kind" (BoardLevel.Kind) and "root" (the folder the
## file was listed from); `load_one(path, kind, root) -> BoardLoadResult` loads one of them
## (BoardLoader.load_listed unless a test passes a slow one). `workers` threads take the
## jobs (1 keeps them in order, as imports that pick free file names must be).
func _init(jobs: Array[Dictionary], load_one := Callable(), workers := WORKERS) -> void:
	_load = load_one if load_one.is_valid() else BoardLoader.load_listed
	_queue = jobs.duplicate()
	for index in mini(workers, _queue.size()):
		var thread := Thread.new()
		_threads.append(thread)
		thread.start(_work, Thread.PRIORITY_LOW)


## The jobs that finished since the last call, each its job dictionary plus "result"
## (a BoardLoadResult), in the order they finished; at most `most` of them when it is not
## negative (the rest wait for the next call).
func take_finished(most := -1) -> Array[Dictionary]:
	_mutex.lock()
	var done := _finished
	_finished = []
	if most >= 0 and done.size() > most:
		_finished = done.slice(most)
		done = done.slice(0, most)
	_mutex.unlock()
	join_ended()
	return done


## True while some file has not finished loading (or a finished one was not taken yet).
## Threads that have ended are joined here: a loading that is not busy holds no thread, so
## dropping it never destroys a thread nobody waited for.
func is_busy() -> bool:
	# Join first, then look at the lists: a thread that ended before the join has put its
	# last result in `_finished` already, so it cannot land after the look.
	var running := not join_ended()
	_mutex.lock()
	var pending := not _queue.is_empty() or not _finished.is_empty()
	_mutex.unlock()
	return running or pending


## Drops the files not started yet; threads busy with a file are joined later, without
## waiting here.
func cancel() -> void:
	_mutex.lock()
	_queue.clear()
	_stopping = true
	_mutex.unlock()
	if not self in _cancelled:
		_cancelled.append(self)
	reap_finished()


## Joins the threads of cancelled loadings that have ended. Cheap; call it now and then.
static func reap_finished() -> void:
	var still_busy: Array[BoardListLoading] = []
	for loading in _cancelled:
		if not loading.join_ended():
			still_busy.append(loading)
	_cancelled = still_busy


## Waits for the threads of every cancelled loading to end and joins them. The game calls
## it as it quits (App._exit_tree): a thread still reading a file when its Thread object is
## destroyed crashes the engine, so quitting waits for at most the one file each is on.
static func wait_for_cancelled() -> void:
	for loading in _cancelled:
		loading.wait()
	_cancelled.clear()


## Drops the files not started yet, waits for the threads to finish the ones they are on
## and drops their results.
func wait() -> void:
	_mutex.lock()
	_queue.clear()
	_stopping = true
	_mutex.unlock()
	for thread in _threads:
		thread.wait_to_finish()
	_threads.clear()
	_mutex.lock()
	_finished.clear()  # nobody takes the results of a loading that was stopped
	_mutex.unlock()


## Joins every thread that has ended (each exactly once); true when none is left running.
func join_ended() -> bool:
	var running: Array[Thread] = []
	for thread in _threads:
		if thread.is_alive():
			running.append(thread)
		else:
			thread.wait_to_finish()
	_threads = running
	return running.is_empty()


func _work() -> void:
	while true:
		_mutex.lock()
		if _queue.is_empty() or _stopping:
			_mutex.unlock()
			return
		var job: Dictionary = _queue.pop_front()
		_mutex.unlock()
		var result: BoardLoadResult = _load.call(job["path"], job["kind"], job["root"])
		var done := job.duplicate()
		done["result"] = result
		_mutex.lock()
		_finished.append(done)
		_mutex.unlock()
