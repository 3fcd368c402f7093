class_name AnalysisWorkerPool
extends PachinkoAnalysis
## A pachinko play analysis split over `workers` worker processes of this binary, headless
## (AnalysisQueueWorker, `--analyze=pachinko --queue=DIR --worker-id=K`): GDScript calls
## contend across threads inside one engine, processes do not. The plan's chunks are cut in
## ranges of RANGE_CHUNKS chunks put in a queue; each worker takes the next range when it is
## done with one, so a slow worker holds back one range, not a share of the run. Each chunk
## is seeded by its index and counted in whole numbers, so the merged counts are the ones
## one thread in this process gives (the same report, timing apart).
##
## Same interface as PachinkoAnalysis: start(), then poll() often; progress(), tally() (the
## ranges done so far), cancel() (kills every worker). With `with_open`, every range also
## runs with the bonus pockets held open (the command line's second run, for
## BonusEstimate): open_tally().
##
## A worker that stops while it holds a range (exits without its counts) or holds one and
## shows no progress for `hang_seconds` (then it is killed) is reported on stderr, naming the
## worker and its chunks, and the range goes back in the queue for another worker; once no
## worker is left, the rest runs here on `plan.threads` threads. No range is dropped.
##
## With `work_here` (the default) this process takes ranges from the queue too, on one
## thread (AnalysisLocalShare): the run starts at once, not after a worker's engine start
## (about 1 s of a core each), so `workers` processes and this one fire together.
##
## The queue's files are AnalysisQueueFolder's job, a worker's command line
## AnalysisWorkerCommand's: this decides who runs which range.

## Chunks in one range of the queue: one chunk (250 shots, about a second of one core) keeps
## the end of a run even; the per-range cost is a few small files.
const RANGE_CHUNKS := 1
## The queue folder is looked at no more often than this, ms.
const POLL_MS := 30
## A worker holding a range with no progress for this long is called hung, seconds (a
## range's slowest step, one chunk or one climb group of Fever, takes a few seconds).
const HANG_SECONDS := 60.0
## Longest a finished run waits for its workers to exit before it kills them, ms.
const EXIT_WAIT_MS := 500

## Worker processes to start (no more than there are ranges).
var workers := 2
## True: each range also runs with the bonus pockets open (open_tally()).
var with_open := false
## The board file the workers load (a path BoardLoader accepts, such as the one the
## command line loaded); "" writes the board's text to the queue folder (the editor's
## board: the figures are then those of the board as its file holds it, 0.01 px).
var board_path := ""
## Seconds without progress after which a worker holding a range is killed as hung.
var hang_seconds := HANG_SECONDS
## True: this process fires ranges of the queue too, beside its workers (set before start()).
var work_here := true
## Why the pool could not start ("" when it did).
var failure := ""
## What went wrong with workers during the run, one line each (also printed on stderr).
var incidents := PackedStringArray()

var _queue := AnalysisQueueFolder.new()
var _pids := PackedInt32Array()
var _beats := PackedStringArray()
var _beat_at := PackedInt64Array()
var _counts: Array[AnalysisTally] = []
var _open_counts: Array[AnalysisTally] = []
var _ranges_done := 0
var _last_look := -POLL_MS
var _here: PachinkoAnalysis = null
var _here_open: PachinkoAnalysis = null
var _here_ranges := PackedInt32Array()
var _merged: AnalysisTally = null
var _merged_open: AnalysisTally = null
var _share: AnalysisLocalShare = null
var _ranges_here := 0


## Worker processes a run uses by default: one per core but the one this process fires on
## when there are more than two cores, else none (0: threads in this process; on two cores
## the workers' start is not paid back on a short run: see scripts/analysis/README.md).
static func default_workers() -> int:
	var cores := OS.get_processor_count()
	return cores - 1 if cores > 2 else 0


## The process ids of the workers started (-1 for those known to be gone).
func process_ids() -> PackedInt32Array:
	return _pids


## How many ranges this process fired itself (`work_here`) so far.
func ranges_here() -> int:
	return _ranges_here


## True while this process's share runs a range (never after cancel() or the end).
func firing_here() -> bool:
	return _share != null and _share.busy()


## Starts the workers. False (with `failure` set) when the plan cannot run this way or no
## worker starts.
func start() -> bool:
	failure = _start_problem()
	if failure.is_empty():
		_started_usec = Time.get_ticks_usec()
		failure = _queue.make(plan, with_open, board_path.is_empty(), RANGE_CHUNKS)
	if not failure.is_empty():
		_queue.remove()
		return false
	_counts.resize(_queue.names.size())
	_open_counts.resize(_queue.names.size())
	var board := board_path if not board_path.is_empty() else _queue.board_path()
	for k in mini(workers, _queue.names.size()):
		_pids.append(AnalysisWorkerCommand.start(plan, board, _queue.path, k))
		_beats.append("")
		_beat_at.append(Time.get_ticks_msec())
	if _pids.count(-1) == _pids.size():
		failure = "could not start %s" % OS.get_executable_path()
		_queue.remove()
		return false
	if work_here:
		_share = AnalysisLocalShare.new()
		var problem := _share.prepare(plan, board, _queue.path, _pids.size(), with_open)
		if not problem.is_empty():
			_report("%s; the workers fire every range" % problem)
			_share = null
	phase = Phase.SHOTS
	return true


## Looks at the queue (at most every POLL_MS): takes in finished ranges, reports and
## requeues a dead or hung worker's range, runs what is left here once no worker is left.
## True once done or cancelled. Never waits.
func poll() -> bool:
	if phase == Phase.DONE or phase == Phase.CANCELLED or phase == Phase.IDLE:
		return phase != Phase.IDLE
	if _here != null:
		return _poll_here()
	if _share != null:
		_take_from_share()
	if Time.get_ticks_msec() - _last_look < POLL_MS:
		return false
	_last_look = Time.get_ticks_msec()
	var files := _queue.files()
	_take_results(files)
	for k in _pids.size():
		_watch(k, files)
	if _ranges_done == _queue.names.size():
		_finish()
		return true
	if _pids.count(-1) == _pids.size() and (_share == null or _share.stopped()):
		_run_rest_here()
	return false


## Kills every worker (and stops the run here, if any); poll() then reports done with phase
## CANCELLED. The counts taken in so far stay.
func cancel() -> void:
	if phase != Phase.SHOTS:
		return
	if _share != null:
		_share.stop()
		_share = null
	_stop_workers()
	if _here != null:
		_here.cancel()
		_here_open = null
	phase = Phase.CANCELLED
	_queue.remove()


## Share of the shots done, 0..1.
func progress() -> float:
	if phase == Phase.DONE:
		return 1.0
	var here := 0.0
	if _here != null:
		var share := _here.progress() if _here_open == null else 1.0 + _here_open.progress()
		here = share / (2.0 if with_open else 1.0) * _here_ranges.size()
	return (_ranges_done + here) / maxf(_queue.names.size(), 1)


## The climbs run inside each range: nothing to wait for before the shots.
func climb_progress() -> float:
	return 0.0 if phase == Phase.IDLE else 1.0


## The counts of the ranges done so far (all of them once done); null before any.
func tally() -> AnalysisTally:
	if phase == Phase.DONE:
		return _merged
	return _merge(_counts)


## With `with_open`: the bonus-open counts once done; else null.
func open_tally() -> AnalysisTally:
	return _merged_open


## Blocking run (the command line, tests): starts and polls until done; the counts, or null
## when the pool could not start.
func run() -> AnalysisTally:
	if not start():
		return null
	while not poll():
		OS.delay_msec(POLL_MS if _here == null and _share == null else 5)
	return _merged if phase == Phase.DONE else null


# Why this plan cannot run on workers, or "".
func _start_problem() -> String:
	var problem := plan.problem()
	if problem.is_empty() and plan.bonus_open:
		problem = "the workers run the bonus-open counts beside the plan's (with_open)"
	if problem.is_empty() and (plan.power_from != 0.0 or plan.power_to != 100.0):
		problem = "workers run only the whole power range"
	if problem.is_empty() and workers < 1:
		problem = "at least one worker is needed (got %d)" % workers
	if problem.is_empty() and not AnalysisWorker.available():
		problem = "this build cannot start worker processes"
	return problem


# Takes in the ranges this process fired (AnalysisLocalShare) and moves its share on.
func _take_from_share() -> void:
	_share.poll()
	for done in _share.take_finished():
		var r := _queue.names.find(str(done["name"]))
		if r >= 0 and _counts[r] == null:
			_counts[r] = done["counts"]
			_open_counts[r] = done["open"]
			_ranges_done += 1
			_ranges_here += 1


# Takes in the counts of every range whose files are there.
func _take_results(files: PackedStringArray) -> void:
	for r in _queue.names.size():
		if _counts[r] != null:
			continue
		var read := _queue.counts_of(r, files, with_open)
		if read.is_empty():
			continue
		if read[0] == null or (with_open and read[1] == null):
			_report(
				(
					"the counts of chunks %s could not be read; running them again"
					% _queue.chunks_text(PackedInt32Array([r]))
				)
			)
			_queue.retry(r)
			continue
		_counts[r] = read[0]
		_open_counts[r] = read[1]
		_ranges_done += 1


# Worker `k`: notes its progress; a worker that stopped, or hangs, holding ranges is
# reported and its ranges go back in the queue.
func _watch(k: int, files: PackedStringArray) -> void:
	if _pids[k] < 0:
		return
	var held := _held(k, files)
	var beat := _queue.beat(k, files)
	var now := Time.get_ticks_msec()
	if beat != _beats[k]:
		_beats[k] = beat
		_beat_at[k] = now
	if not OS.is_process_running(_pids[k]):
		var code := OS.get_process_exit_code(_pids[k])
		if not held.is_empty():
			_report(
				(
					(
						"worker %d (process %d) stopped (exit code %d) without the counts of chunks %s;"
						% [k, _pids[k], code, _queue.chunks_text(held)]
					)
					+ " running them again"
				)
			)
		_pids[k] = -1
	elif not held.is_empty() and now - _beat_at[k] > hang_seconds * 1000.0:
		_report(
			(
				(
					"worker %d (process %d) made no progress for %d s on chunks %s;"
					% [k, _pids[k], roundi(hang_seconds), _queue.chunks_text(held)]
				)
				+ " killed, running them again"
			)
		)
		OS.kill(_pids[k])
		_pids[k] = -1
	else:
		return
	for r in held:
		_queue.give_back(k, r)


# The ranges worker `k` took and has not finished.
func _held(k: int, files: PackedStringArray) -> PackedInt32Array:
	var out := PackedInt32Array()
	for r in _queue.taken_by(k, files):
		if _counts[r] == null:
			out.append(r)
	return out


func _report(line: String) -> void:
	incidents.append(line)
	printerr("analysis: %s" % line)


# No worker is left: the ranges not done run here, on plan.threads threads.
func _run_rest_here() -> void:
	var chunks := PackedInt32Array()
	for r in _queue.names.size():
		if _counts[r] == null:
			_here_ranges.append(r)
			chunks.append_array(AnalysisQueueWorker.chunks_of(_queue.names[r]))
	_report("no worker left; running chunks %s here" % _queue.chunks_text(_here_ranges))
	_here = PachinkoAnalysis.new(plan)
	_here.only_chunks = chunks
	if not _here.start():
		_here = null
		phase = Phase.CANCELLED
		_queue.remove()


func _poll_here() -> bool:
	if not _here.poll():
		return false
	if _here.phase != Phase.DONE:
		phase = Phase.CANCELLED
		_queue.remove()
		return true
	if with_open and _here_open == null:
		_here_open = PachinkoAnalysis.new(plan.with_bonus_open())
		_here_open.only_chunks = _here.only_chunks
		_here_open.reuse_climbs(_here.climb_table())
		if _here_open.start():
			return false
		phase = Phase.CANCELLED
		_queue.remove()
		return true
	# The counts of all the ranges run here stand in the first one's place (whole numbers:
	# the merge adds them up the same).
	var r := _here_ranges[0]
	_counts[r] = _here.tally()
	if with_open:
		_open_counts[r] = _here_open.tally()
	_ranges_done += _here_ranges.size()
	_here = null
	_here_open = null
	_finish()
	return true


# All ranges are in: merges them, tells the workers to go and removes the queue.
func _finish() -> void:
	_merged = _merge(_counts)
	_merged_open = _merge(_open_counts) if with_open else null
	wall_seconds = (Time.get_ticks_usec() - _started_usec) / 1e6
	phase = Phase.DONE
	if _share != null:
		_share.stop()
		_share = null
	_queue.close()
	_queue.remove()
	# The workers see the queue gone within IDLE_MS and exit; waiting for that here reaps
	# them (no process is left behind), and any still there is killed.
	var waited := 0
	while _pids.count(-1) < _pids.size() and waited < EXIT_WAIT_MS:
		for k in _pids.size():
			if _pids[k] > 0 and not OS.is_process_running(_pids[k]):
				_pids[k] = -1
		OS.delay_msec(5)
		waited += 5
	_stop_workers()


# The counts in `parts` (nulls skipped) added up; null when there are none. Whole numbers:
# the order does not change them.
func _merge(parts: Array[AnalysisTally]) -> AnalysisTally:
	var merged: AnalysisTally = null
	for part in parts:
		if part == null:
			continue
		if merged == null:
			merged = AnalysisTally.new(
				BonusGeometry.world_pockets(plan.level).size(), plan.level.size
			)
		merged.merge(part)
	return merged


func _stop_workers() -> void:
	for k in _pids.size():
		if _pids[k] > 0 and OS.is_process_running(_pids[k]):
			OS.kill(_pids[k])
		_pids[k] = -1
