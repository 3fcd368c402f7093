extends RefCounted
## Splits a per-ball stage over worker threads: balls 0..n are cut into contiguous ranges
## ("lanes"), one per thread, run as one high-priority WorkerThreadPool group task (the
## pool gives low-priority work only a share of its threads: one thread on two cores).
## Internal to scripts/physics.
##
## A stage run this way must read only the last state and write only its own balls (and
## its lane's own output buffers, merged afterwards in lane order): then the result does
## not depend on how many lanes there were, and 1, 2 or 4 threads give bit-identical
## worlds. Packed arrays are shared by reference here; a stage must never resize or
## reassign an array that another lane writes.

## A lane gets at least this many balls: below it, waking a thread costs more than it saves.
const MIN_BALLS_PER_LANE := 48

## Threads a stage may use (1 runs everything on the calling thread).
var threads := 1

var _job := Callable()
var _count := 0
var _lanes := 1


## How many lanes a stage over `count` balls uses.
func lanes_for(count: int) -> int:
	return clampi(count / MIN_BALLS_PER_LANE, 1, maxi(threads, 1))


## Calls `job(lane, from, to)` once per lane, covering 0..count without overlap, and
## returns once every lane is done. Returns the number of lanes used.
func run(job: Callable, count: int) -> int:
	var lanes: int = lanes_for(count)
	if lanes == 1:
		job.call(0, 0, count)
		return 1
	_job = job
	_count = count
	_lanes = lanes
	# Lanes 1.. go to the pool; this thread runs lane 0 meanwhile instead of only waiting.
	var task: int = WorkerThreadPool.add_group_task(
		_run_pool_lane, lanes - 1, lanes - 1, true, "BallWorld lanes"
	)
	_run_lane(0)
	WorkerThreadPool.wait_for_group_task_completion(task)
	_job = Callable()
	return lanes


func _run_pool_lane(task: int) -> void:
	_run_lane(task + 1)


func _run_lane(lane: int) -> void:
	_job.call(lane, _count * lane / _lanes, _count * (lane + 1) / _lanes)
