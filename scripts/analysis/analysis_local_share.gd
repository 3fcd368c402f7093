class_name AnalysisLocalShare
extends RefCounted
## The parent's own share of a pooled run (AnalysisWorkerPool): this process takes ranges
## from the same queue as its worker processes, by the same rename (AnalysisQueueWorker.take:
## only one taker wins a range), and fires them here on one worker thread, so the run starts
## at once instead of waiting about a second for each worker's engine to start. Driven by
## poll() from the pool's poll(): it never waits.
##
## It loads the board from the file the workers load (the command line's board file, or the
## board text the pool wrote to the queue folder), so its chunks' counts are the workers'
## (a board in the editor's memory can differ from its file text by under 0.01 px).

## One finished range: {"name": its queue name, "counts": AnalysisTally, "open": the
## bonus-open counts or null}. Set by poll(); the pool takes it with take_finished().
var finished: Array[Dictionary] = []

var _folder := ""
var _id := -1
var _with_open := false
var _plans: Array[AnalysisPlan] = []
var _name := ""
var _runs_left: Array[AnalysisPlan] = []
var _counts: Array[AnalysisTally] = []
var _run: PachinkoAnalysis = null
var _climbs: RailExitTable = null
var _stopped := false


## Readies the share for the queue in `folder` (an absolute path) as taker `id` (a number
## no worker process has), loading `board` (a board file's path, res:// or user://, as the
## pool hands its workers) for `plan`'s shots,
## seed and kind of run. "" or why it cannot work here (then the workers do it all).
func prepare(plan: AnalysisPlan, board: String, folder: String, id: int, with_open: bool) -> String:
	var roots := BoardLoader.BOARD_ROOTS.duplicate()
	roots.append(AnalysisWorker.FOLDER + "/")  # the editor's board, written to the queue
	var loaded := BoardLoader.load_board(board, roots)
	if loaded.level == null:
		return "the board for this process's share: %s" % loaded.error
	var own := AnalysisPlan.create(loaded.level, plan.shots, plan.rng_seed)
	own.played = plan.played
	own.threads = 1
	_plans = [own]
	if with_open:
		_plans.append(own.with_bonus_open())
	_folder = folder
	_id = id
	_with_open = with_open
	return ""


## True while it holds a range it has not finished.
func busy() -> bool:
	return not _name.is_empty()


## True once it stopped (stop(), or a run here failed): it takes no more ranges.
func stopped() -> bool:
	return _stopped


## Moves the share on: finishes the runs of the range it holds, or takes the next waiting
## range. Finished ranges go to `finished`. Call it often; it never waits.
func poll() -> void:
	if _stopped or _plans.is_empty():
		return
	if _run != null:
		if not _run.poll():
			return
		if _run.phase != PachinkoAnalysis.Phase.DONE:
			_run = null
			_give_back()
			return
		_climbs = _run.climb_table()
		_counts.append(_run.tally())
		_run = null
	if busy() and _runs_left.is_empty():
		finished.append(
			{"name": _name, "counts": _counts[0], "open": _counts[1] if _with_open else null}
		)
		DirAccess.remove_absolute(_folder.path_join("took_%d_%s" % [_id, _name]))
		_name = ""
	if not busy():
		_name = AnalysisQueueWorker.take(_folder, _id)
		if _name.is_empty():
			return
		_runs_left = _plans.duplicate()
		_counts.clear()
	_start_next()


## The ranges finished since the last call (each handed out once).
func take_finished() -> Array[Dictionary]:
	var out := finished
	finished = []
	return out


## Stops: the run in hand is cancelled and waited for (a chunk's shots stop between shots),
## and the range it held goes back in the queue.
func stop() -> void:
	if _run != null:
		_run.cancel()
		while not _run.poll():
			OS.delay_msec(2)
		_run = null
	_give_back()


func _start_next() -> void:
	var next: AnalysisPlan = _runs_left.pop_front()
	_run = PachinkoAnalysis.new(next)
	_run.only_chunks = AnalysisQueueWorker.chunks_of(_name)
	if _climbs != null:
		_run.reuse_climbs(_climbs)
	if not _run.start():
		_run = null
		_give_back()


# No more work here: the range held (if any) goes back in the queue for the workers.
func _give_back() -> void:
	_stopped = true
	if busy():
		DirAccess.rename_absolute(
			_folder.path_join("took_%d_%s" % [_id, _name]), _folder.path_join("todo_" + _name)
		)
		_name = ""
