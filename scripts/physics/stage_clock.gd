class_name StageClock
extends RefCounted
## Wall time spent in each stage of BallWorld.step(), for the bench and for finding where a
## step's time goes. Off in play: the world only laps it while BallWorld.profile_stages is
## on. Internal to scripts/physics.

## The stages, in the order a step runs them, timed where the schedule the game runs
## has its boundaries: the broad phase's lanes answer the even stripes of ball pairs as
## they list them (FIND_AND_SOLVE_EVEN), then the odd stripes are answered (SOLVE_ODD); the
## sleepers are settled in the motion stage.
enum Stage { INTEGRATE, FIND_AND_SOLVE_EVEN, SOLVE_ODD, MOTION, EVENTS }

## Names of the stages, as stage_times() reports them.
const NAMES: Array[String] = ["integrate", "find_and_solve_even", "solve_odd", "motion", "events"]

## Microseconds spent per stage since the last reset, and steps timed.
var usec := PackedInt64Array()
var steps := 0
## True counts the CPU time of the world's thread (Linux: /proc/thread-self/schedstat, in
## ns) instead of wall time: on a busy machine the wall clock also counts the time other
## programs held the core. Only the world's thread: pool threads are not counted.
var cpu_time := false
## Off: start() and lap() return at once (the world calls them every step).
var enabled := false
## True appends each lapped stage to `laps`, timed or not (tests compare schedules).
var recording := false
var laps := PackedInt32Array()
var _mark := 0


func _init() -> void:
	reset()


func reset() -> void:
	usec.resize(NAMES.size())
	usec.fill(0)
	steps = 0


## Starts timing a step.
func start() -> void:
	if enabled:
		_mark = _now()


## Charges the time since the last mark to `stage`; `step_done` counts a whole step.
func lap(stage: int, step_done := false) -> void:
	if recording:
		laps.append(stage)
	if not enabled:
		return
	if step_done:
		steps += 1
	var now: int = _now()
	usec[stage] += now - _mark
	_mark = now


## Average microseconds per step of each stage, by name, plus "total".
func per_step() -> Dictionary:
	var out := {}
	var total := 0.0
	for s: int in NAMES.size():
		var us: float = float(usec[s]) / maxi(steps, 1)
		out[NAMES[s]] = us
		total += us
	out["total"] = total
	return out


func _now() -> int:
	if not cpu_time:
		return Time.get_ticks_usec()
	var f := FileAccess.open("/proc/thread-self/schedstat", FileAccess.READ)
	if f == null:
		cpu_time = false
		return Time.get_ticks_usec()
	# First field: nanoseconds this thread has run (whole microseconds are enough).
	@warning_ignore("integer_division")
	return int(f.get_line().get_slice(" ", 0)) / 1000
