class_name BallLanes
extends RefCounted
## Splits a per-ball stage over worker threads: balls 0..n are cut into contiguous ranges
## ("lanes"), a few per thread. The calling thread and the workers of a LaneCrew (threads
## of this object's own) each take the next lane not yet taken until none is left: a
## worker that wakes late, or that another program holds off its core, then leaves its
## share to the others, and the stage does not wait for it. Several small lanes per thread
## even out the load, as sleeping balls and crowded cells are not spread evenly. Internal to
## scripts/physics.
##
## A stage run this way must read only the last state and write only its own balls (and
## its lane's own output buffers, merged afterwards in lane order): then the result does
## not depend on how many lanes there were or which thread ran which, and 1, 2 or 4 threads
## give bit-identical worlds. Packed arrays are shared by reference here; a stage must never
## resize or reassign an array that another lane writes.

## A lane gets at least this many balls: below it, handing it out costs more than it saves.
const MIN_BALLS_PER_LANE := 48
## Lanes per thread, at most.
const LANES_PER_THREAD := 4
## See tapered_bounds(): the last lane's share, in parts (lane k has TAPER_TOP + lanes - k).
const TAPER_TOP := 2

## Threads a stage may use (1 runs everything on the calling thread).
var threads := 1

var _crew := LaneCrew.new()
## False in a build without threads (a single-threaded web export): there a started Thread
## never runs, so every stage stays on the calling thread.
var _can_thread: bool = OS.has_feature("threads")


## The crew of worker threads the lanes run on (tests count its started workers).
func crew() -> LaneCrew:
	return _crew


func _notification(what: int) -> void:
	if what == NOTIFICATION_PREDELETE:
		_crew.stop()


## How many lanes a stage over `count` balls uses: 1 when threads is 1, and 1 inside a
## WorkerThreadPool task (worlds stepped side by side on every core already fill the pool;
## waiting there for more pool tasks could block every pool thread at once).
func lanes_for(count: int) -> int:
	if threads <= 1 or not _can_thread or _in_pool_task():
		return 1
	@warning_ignore("integer_division")  # whole lanes of at least MIN_BALLS_PER_LANE balls
	var most_lanes := count / MIN_BALLS_PER_LANE
	return clampi(most_lanes, 1, threads * LANES_PER_THREAD)


## Workers (threads, the calling one included) a stage over `count` balls runs on.
func workers_for(count: int) -> int:
	return mini(threads, lanes_for(count))


## Calls `job(lane, from, to)` once per lane, covering 0..count without overlap, and
## returns once every lane is done. Returns the number of lanes used.
func run(job: Callable, count: int) -> int:
	return _run(job, tapered_bounds(count, lanes_for(count)), false)


## As run(), but calls `job(worker, lane, from, to)`: `worker` (0 is the calling thread,
## below workers_for(count)) lets a stage keep one set of working state per thread.
func run_by_worker(job: Callable, count: int) -> int:
	return _run(job, tapered_bounds(count, lanes_for(count)), true)


## As run_by_worker(), over lanes the caller cut: lane k covers items bounds[k] ..
## bounds[k + 1] (items may be anything, e.g. rows of cells; bounds must not decrease).
func run_spans(job: Callable, bounds: PackedInt32Array) -> int:
	return _run(job, bounds, true)


## Bounds of `lanes` lanes over `count` items, each lane smaller than the one before (lane
## k's share is TAPER_TOP + lanes - k parts, so the last is about a third of the first):
## the threads take the big lanes first, and the small ones at the end even out who
## finishes last (even lanes left one thread up to a whole lane behind the other).
static func tapered_bounds(count: int, lanes: int) -> PackedInt32Array:
	var bounds := PackedInt32Array()
	bounds.resize(lanes + 1)
	@warning_ignore("integer_division")  # parts: lanes·(lanes + 1) / 2 + TAPER_TOP·lanes
	var parts: int = lanes * (lanes + 1) / 2 + TAPER_TOP * lanes
	var before := 0
	for k: int in lanes + 1:
		@warning_ignore("integer_division")
		bounds[k] = count * before / parts
		before += TAPER_TOP + lanes - k
	bounds[lanes] = count
	return bounds


# Runs `job` over the lanes `bounds` cut; `with_worker` says it takes a worker number.
func _run(job: Callable, bounds: PackedInt32Array, with_worker: bool) -> int:
	var lanes: int = bounds.size() - 1
	if lanes == 1 or threads <= 1 or not _can_thread or _in_pool_task():
		for lane: int in lanes:
			if with_worker:
				job.call(0, lane, bounds[lane], bounds[lane + 1])
			else:
				job.call(lane, bounds[lane], bounds[lane + 1])
		return lanes
	_crew.run(job, bounds, mini(threads, lanes) - 1, with_worker)
	return lanes


static func _in_pool_task() -> bool:
	return WorkerThreadPool.get_caller_task_id() >= 0 or WorkerThreadPool.get_caller_group_id() >= 0
