class_name LaneCrew
extends RefCounted
## The worker threads of one BallLanes: each waits for a hand-off, then takes lanes until
## none is left. The thread that hands off takes lanes too, and once every lane is taken it
## waits only for the lanes others are still running, never for a worker that has not woken
## yet: on a busy machine a worker may wake a few milliseconds late, and a stage that waited
## for it (as a WorkerThreadPool group task must) would take longer on two threads than on
## one. A late worker finds nothing left and goes back to waiting.
##
## Between hand-offs nobody sleeps at once. A thread woken from a semaphore starts 30-100 us
## late on a virtual machine, and a step hands off two or three times with about 300 us of
## work each: sleeping there cost a quarter of every stage. So a worker first watches the
## hand-off counter for SPIN_CHECKS reads (about half a millisecond), and the handing-off
## thread watches the lanes-done count the same way before it sleeps; and the lock that
## hands out lanes is taken by trying (see _lock()), never by sleeping on it. The watching loops
## read members and call nothing: a GDScript call on one thread slows down calls on every
## other (measured: two threads of calls run no faster than one), while call-free loops
## run side by side at full speed.
##
## Internal to scripts/physics. The crew holds no reference to its BallLanes, so the lanes
## object can be freed while the threads wait; it then calls stop(), which joins them.

## Member reads a watching thread makes before it sleeps: about half a millisecond.
const SPIN_CHECKS := 20000

## Workers started so far (the handing-off thread is not one of them).
var started := 0

var _threads: Array[Thread] = []
var _wake := Semaphore.new()
var _all_done := Semaphore.new()
var _taking := Mutex.new()
var _stopping := false
## The hand-off being worked, under _taking: its job, lane bounds, the workers it may use,
## the next lane nobody has taken, lanes finished, whether the handing-off thread waits
## for the rest, and whether the job takes a worker number.
var _job := Callable()
var _bounds := PackedInt32Array()
var _helpers := 0
var _next_lane := 0
var _lanes_done := 0
var _caller_waiting := false
var _with_worker := true
## Hand-offs so far: a watching worker sees a new one by its number (written under _taking).
var _generation := 0
## Workers asleep on _wake (under _taking): only they need a post.
var _sleepers := 0


## Runs `job` over the lanes cut by `bounds` (lane k covers bounds[k] .. bounds[k + 1]) on
## the calling thread and up to `helpers` workers, started on first need. `job` is called
## as job(worker, lane, from, to), or job(lane, from, to) when `with_worker` is false; the
## calling thread is worker 0, and workers above `helpers` sit this one out. Returns once
## every lane is done.
func run(job: Callable, bounds: PackedInt32Array, helpers: int, with_worker: bool) -> void:
	while started < helpers:
		var thread := Thread.new()
		_threads.append(thread)
		started += 1
		thread.start(_work.bind(started))
	var lanes: int = bounds.size() - 1
	_lock()
	_job = job
	_bounds = bounds
	_helpers = helpers
	_with_worker = with_worker
	_next_lane = 0
	_lanes_done = 0
	_caller_waiting = false
	_generation += 1
	var posts: int = mini(_sleepers, mini(helpers, lanes - 1))
	_sleepers -= posts
	_taking.unlock()
	for _k: int in posts:
		_wake.post()
	_take_lanes(0)
	# The others hold one lane each at most: watch for them before sleeping.
	var checks := 0
	while _lanes_done < lanes and checks < SPIN_CHECKS:
		checks += 1
	_lock()
	var wait: bool = _lanes_done < lanes
	_caller_waiting = wait
	_taking.unlock()
	if wait:
		_all_done.wait()
	_lock()
	_job = Callable()
	_taking.unlock()


## Stops and joins every worker. Call once, when the crew is no longer used.
func stop() -> void:
	_taking.lock()
	_stopping = true
	_taking.unlock()
	for _thread: Thread in _threads:
		_wake.post()
	for thread: Thread in _threads:
		thread.wait_to_finish()
	_threads.clear()
	started = 0


func _work(worker: int) -> void:
	var seen := 0
	while true:
		_lock()
		var stopping: bool = _stopping
		var fresh: bool = _generation != seen
		if not fresh and not stopping:
			_sleepers += 1
		_taking.unlock()
		if stopping:
			return
		if not fresh:
			_wake.wait()
		_lock()
		seen = _generation
		_taking.unlock()
		_take_lanes(worker)
		var checks := 0
		while _generation == seen and not _stopping and checks < SPIN_CHECKS:
			checks += 1


## Takes and runs lanes of the current hand-off on `worker` until none is left. The one
## who finishes the last lane wakes the handing-off thread if it is waiting.
func _take_lanes(worker: int) -> void:
	while true:
		_lock()
		var lane: int = _next_lane
		var lanes: int = _bounds.size() - 1
		if _job.is_null() or lane >= lanes or worker > _helpers:
			_taking.unlock()
			return
		_next_lane += 1
		var job: Callable = _job
		var from: int = _bounds[lane]
		var to: int = _bounds[lane + 1]
		var with_worker: bool = _with_worker
		_taking.unlock()
		if with_worker:
			job.call(worker, lane, from, to)
		else:
			job.call(lane, from, to)
		_lock()
		_lanes_done += 1
		var wake_caller: bool = _lanes_done == lanes and _caller_waiting
		_taking.unlock()
		if wake_caller:
			_all_done.post()


## Takes _taking by trying until it is free. Every hold is a few lines long, and a thread
## that blocked on the lock instead would sleep in the kernel and wake 15-40 us late: as
## late as a worker woken by a semaphore, at every lane taken.
func _lock() -> void:
	while not _taking.try_lock():
		pass
