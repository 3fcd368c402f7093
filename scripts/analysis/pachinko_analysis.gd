class_name PachinkoAnalysis
extends RefCounted
## Runs a pachinko play analysis (an AnalysisPlan) on worker threads, blocking (run()) or
## in the background (start(), then poll() each frame; cancel() stops it). Two phases, each
## one high-priority WorkerThreadPool group task: the rail climbs of the power levels the
## shots use (RailExitTable), then the chunks of shots (PachinkoShotChunk), each in its own
## world. Chunk results are merged in chunk order, so the figures depend only on the plan,
## never on the thread count or which thread finished first.

## IDLE: not started; CLIMBS, SHOTS: the two phases; DONE; CANCELLED.
enum Phase { IDLE, CLIMBS, SHOTS, DONE, CANCELLED }

var plan: AnalysisPlan
var phase := Phase.IDLE
## Seconds from start to done (wall clock).
var wall_seconds := 0.0
## Set before start() to time the run's stages into it (AnalysisProfile); null: untimed.
var profile: AnalysisProfile = null
## Set before start() to run only these chunk indices (a worker process's share, see
## AnalysisQueueWorker); empty runs every chunk. Each chunk is seeded by its index, so a
## chunk's counts are the same whoever runs it, and tally() holds only these chunks'.
var only_chunks := PackedInt32Array()

var _launch_table: LaunchTable
var _table := RailExitTable.new()
var _groups: Array[PackedInt32Array] = []
var _group_results: Array[RailExitTable] = []
var _chunk_results: Array[AnalysisTally] = []
# The chunk indices this run fires (every chunk, or only_chunks), in order.
var _chunk_list := PackedInt32Array()
# True once reuse_climbs() handed this run another run's climbs.
var _table_handed := false
var _chunks_done := 0
var _task := -1
var _cancelled := false
var _mutex := Mutex.new()
var _started_usec := 0
## True in run() with one thread: the work then runs on the calling thread itself.
var _inline := false


func _init(p_plan: AnalysisPlan) -> void:
	plan = p_plan


## Runs the whole analysis on the calling thread and `plan.threads` threads; returns the
## tally, or null with an error for a plan that cannot run.
func run() -> AnalysisTally:
	_inline = plan.threads <= 1
	if not start():
		return null
	while not poll():
		if _task >= 0:
			WorkerThreadPool.wait_for_group_task_completion(_task)
			_task = -1
	var mark := Time.get_ticks_usec()
	var merged := tally()
	if profile != null:
		profile.add_usec(AnalysisProfile.Stage.MERGE, Time.get_ticks_usec() - mark)
	return merged


## Hands this analysis the rail climbs of an earlier one on the same board (its
## climb_table()): call before start(). Only the power levels it lacks are climbed (into
## that table, which grows), none when it holds every level the plan fires (a rail climb
## never depends on the plan: the climb world has the bonus parts shut, as
## BoardWorldFactory builds them), and the figures are the same.
func reuse_climbs(table: RailExitTable) -> void:
	if phase == Phase.IDLE and table != null:
		_table = table
		_table_handed = true


## The rail climbs the analysis ran or was handed (complete once it is done).
func climb_table() -> RailExitTable:
	return _table


## Begins the analysis in the background. False (with an error) for a bad plan.
func start() -> bool:
	var problem := plan.problem()
	if not problem.is_empty():
		push_error("PachinkoAnalysis: %s" % problem)
		return false
	_started_usec = Time.get_ticks_usec()
	# Measured here, on one thread: LaunchCalibration's cache is not thread-safe.
	_launch_table = LaunchCalibration.table(plan.level)
	if profile != null:
		profile.add_usec(AnalysisProfile.Stage.LAUNCH_TABLE, Time.get_ticks_usec() - _started_usec)
	_chunk_list = _chunks_to_run()
	if _chunk_list.is_empty():
		push_error("PachinkoAnalysis: only_chunks names no chunk of the plan")
		return false
	# A played run's shots meet other balls, so its table follows each climb on to its
	# first pin; a contact-free run's chunks record the first pins past the hand-over.
	if not _table_handed or (plan.played and not _table.to_first_pin):
		_table = RailExitTable.new()
		_table.to_first_pin = plan.played
	# Only the levels not climbed yet (all of them for a fresh table): a climb depends on
	# its power level only, never on the levels climbed beside it.
	var missing := PackedByteArray()
	missing.resize(AnalysisPlan.level_count())
	for c in _chunk_list:
		for q in plan.chunk_levels(c):
			if _table.fate[q] == RailExitTable.Fate.UNKNOWN:
				missing[q] = 1
	_groups = RailExitTable.groups_for(missing)
	_group_results.resize(_groups.size())
	_chunk_results.resize(plan.chunk_count())
	phase = Phase.CLIMBS
	_launch(_climb_group, _groups.size())
	return true


## Moves the analysis on; call it often (each frame). Returns true once it is done or
## cancelled. Never waits for the workers.
func poll() -> bool:
	if phase == Phase.DONE or phase == Phase.CANCELLED or phase == Phase.IDLE:
		return phase != Phase.IDLE
	if _task >= 0 and not WorkerThreadPool.is_group_task_completed(_task):
		return false
	if _task >= 0:
		WorkerThreadPool.wait_for_group_task_completion(_task)
		_task = -1
	if _cancelled:
		phase = Phase.CANCELLED
	elif phase == Phase.CLIMBS:
		for g in _groups.size():
			_table.store(_group_results[g], _groups[g])
		_group_results.clear()
		phase = Phase.SHOTS
		_launch(_run_chunk, _chunk_list.size())
		return false
	else:
		phase = Phase.DONE
	wall_seconds = (Time.get_ticks_usec() - _started_usec) / 1e6
	return true


## Asks the workers to stop; poll() then reports done with phase CANCELLED.
func cancel() -> void:
	_cancelled = true


## Share of the work done, 0..1 (by chunks of shots).
func progress() -> float:
	if phase == Phase.DONE:
		return 1.0
	_mutex.lock()
	var done := _chunks_done
	_mutex.unlock()
	return float(done) / maxf(_chunk_list.size(), 1)


## Share of the rail climbs done, 0..1 (by climb groups; 1 once the shots began).
func climb_progress() -> float:
	if phase != Phase.CLIMBS:
		return 1.0 if phase != Phase.IDLE else 0.0
	var done := 0
	_mutex.lock()
	for part in _group_results:
		if part != null:
			done += 1
	_mutex.unlock()
	return float(done) / maxf(_groups.size(), 1)


## Shots finished so far (the chunks done, whole).
func shots_done() -> int:
	var t := tally()
	return t.total_shots() if t != null else 0


## The merged counts of every chunk finished so far, in chunk order (all of them once
## done); null before any chunk finished.
func tally() -> AnalysisTally:
	var merged: AnalysisTally = null
	_mutex.lock()
	for chunk_tally in _chunk_results:
		if chunk_tally == null:
			continue
		if merged == null:
			merged = AnalysisTally.new(
				BonusGeometry.world_pockets(plan.level).size(), plan.level.size
			)
		merged.merge(chunk_tally)
	_mutex.unlock()
	return merged


# The chunk indices to fire: only_chunks (those within the plan), or every chunk.
func _chunks_to_run() -> PackedInt32Array:
	var out := PackedInt32Array()
	if only_chunks.is_empty():
		out.resize(plan.chunk_count())
		for c in out.size():
			out[c] = c
		return out
	for c in only_chunks:
		if c >= 0 and c < plan.chunk_count() and not out.has(c):
			out.append(c)
	return out


# Runs `job(index)` for index 0..count-1: on this thread for a blocking one-thread run,
# else as one high-priority group task (low-priority tasks get a single thread on two
# cores), so a background run never blocks its caller.
func _launch(job: Callable, count: int) -> void:
	if count == 0:
		return
	if _inline:
		for i in count:
			job.call(i)
		return
	_task = WorkerThreadPool.add_group_task(
		job, count, clampi(plan.threads, 1, count), true, "Play analysis"
	)


func _climb_group(g: int) -> void:
	if _cancelled:
		return
	var mark := Time.get_ticks_usec()
	var timed := AnalysisProfile.new() if profile != null else null
	var part := RailClimber.climb_group(
		plan.level, _launch_table, _groups[g], timed, _table.to_first_pin
	)
	_mutex.lock()
	_group_results[g] = part
	if timed != null:
		timed.add_usec(AnalysisProfile.Stage.CLIMB, Time.get_ticks_usec() - mark)
		profile.add(timed)
	_mutex.unlock()


func _run_chunk(i: int) -> void:
	if _cancelled:
		return
	var c := _chunk_list[i]
	var stop := func() -> bool: return _cancelled
	var counts: AnalysisTally = null
	var timed: AnalysisProfile = null
	if plan.played:
		var played := PlayedShotChunk.new(plan, _launch_table, _table)
		counts = played.tally if played.run(c, stop) else null
	else:
		var lone := PachinkoShotChunk.new(plan, _launch_table, _table)
		lone.profile = AnalysisProfile.new() if profile != null else null
		counts = lone.tally if lone.run(c, stop) else null
		timed = lone.profile
	if counts == null:
		return
	_mutex.lock()
	_chunk_results[c] = counts
	_chunks_done += 1
	if timed != null:
		profile.add(timed)
	_mutex.unlock()
