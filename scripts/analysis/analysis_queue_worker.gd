class_name AnalysisQueueWorker
extends RefCounted
## The worker process's side of AnalysisWorkerPool (`--analyze=pachinko --queue=DIR
## --worker-id=K`, see analyze_cli.gd): takes chunk ranges from the queue folder DIR one at a
## time, fires their chunks on one thread (PachinkoAnalysis.only_chunks: each chunk seeded by
## its index, so its counts are the ones any process gives it) and writes their counts back,
## until the parent closes the queue, removes the folder or is gone.
##
## The queue is plain files in DIR, so a worker needs no pipe to its parent:
## - `todo_NAME`: a range waiting (NAME is `rFIRST-LAST`, chunk indices);
## - `took_K_NAME`: worker K took it (a rename, which only one worker can win);
## - `done_NAME.tally` (and `done_NAME.open.tally` for the bonus-open run): its counts
##   (AnalysisTally.to_bytes()), written aside and renamed, so the parent never reads half;
## - `beat_K`: a number worker K raises whenever its work moves on (a range taken, a climb
##   group or a chunk done): the parent calls a worker that holds a range and does not
##   raise it for a while hung;
## - `job.json` (from the parent): {"parent": its process id, "with_open": true when each
##   range also runs with the bonus pockets held open, for BonusEstimate};
## - `closed` (from the parent): no more work; the workers exit.
##
## A worker climbs the rail only for the power levels its ranges fire, and keeps the climbs
## for its next ranges (a climb depends on its power level only). Chosen over the parent
## climbing every level first and handing the table over: the ranges' levels barely overlap
## (10000 shots fire 10000 of the 10001 levels once), so the workers climb about the levels
## one thread climbs, and no worker waits for a climb phase that is about a third of a
## one-thread run (Classic, 500 shots: climbs 0.32 s of 0.95 s, make bench's profile).
##
## Test hook: the environment variable FAULT_ENV, read only here, makes one worker fail on
## purpose once it took its first range: `die:K` (worker K kills itself, leaving its range
## taken and its counts unwritten) or `hang:K` (worker K stops working but stays alive).

## Names the worker to fail and how: `die:K` or `hang:K` (K: the worker id). Tests only.
const FAULT_ENV := "BOARD_STUDIO_ANALYSIS_WORKER_FAULT"
## How long an idle worker waits before looking at the queue again, ms.
const IDLE_MS := 20
const EXIT_OK := 0
const EXIT_FAILED := 1


## Runs worker `id` on the queue in `folder` (an absolute path) for `plan` (its `threads`
## is ignored: a worker fires on one thread; processes, not threads, share the cores).
## Returns the exit code.
static func run(plan: AnalysisPlan, folder: String, id: int) -> int:
	var parsed: Variant = JSON.parse_string(_text(folder.path_join("job.json")))
	if not parsed is Dictionary:
		printerr("analyze: worker %d: no job.json in %s" % [id, folder])
		return EXIT_FAILED
	var job: Dictionary = parsed
	var parent_number: float = job.get("parent", -1.0)  # JSON numbers are floats
	var parent_pid := roundi(parent_number)
	var with_open: bool = job.get("with_open", false) == true
	plan.threads = 1
	var table: RailExitTable = null
	var beats := 0
	while _wanted(folder, parent_pid):
		var name := take(folder, id)
		if name.is_empty():
			OS.delay_msec(IDLE_MS)
			continue
		beats += 1
		SafeWrite.write_bytes(folder.path_join("beat_%d" % id), str(beats).to_utf8_buffer())
		_fault(id, folder, parent_pid)
		var runs: Array[AnalysisPlan] = [plan]
		if with_open:
			runs.append(plan.with_bonus_open())
		var counts: Array[AnalysisTally] = []
		for run_plan in runs:
			var analysis := PachinkoAnalysis.new(run_plan)
			analysis.only_chunks = chunks_of(name)
			if table != null:
				analysis.reuse_climbs(table)
			if not analysis.start():
				return EXIT_FAILED
			var said := -1.0
			while not analysis.poll():
				var moved := analysis.climb_progress() + analysis.progress()
				if moved != said:
					said = moved
					beats += 1
					SafeWrite.write_bytes(
						folder.path_join("beat_%d" % id), str(beats).to_utf8_buffer()
					)
				if not _wanted(folder, parent_pid):
					analysis.cancel()
					while not analysis.poll():
						OS.delay_msec(IDLE_MS)
					return EXIT_OK
				OS.delay_msec(IDLE_MS)
			table = analysis.climb_table()
			counts.append(analysis.tally())
		# The open run's counts first: the parent takes the range as done once the shut
		# run's file is there.
		if (
			with_open
			and (
				SafeWrite.write_bytes(
					folder.path_join("done_%s.open.tally" % name), counts[1].to_bytes()
				)
				!= OK
			)
		):
			return EXIT_FAILED
		if (
			SafeWrite.write_bytes(folder.path_join("done_%s.tally" % name), counts[0].to_bytes())
			!= OK
		):
			return EXIT_FAILED
		DirAccess.remove_absolute(folder.path_join("took_%d_%s" % [id, name]))
	return EXIT_OK


## True while the queue in `folder` may still hold work: the folder is there and not closed.
## A worker started after its run ended (this process's share can finish a short run before
## a worker's engine has started) finds it gone and exits without a word.
static func queue_open(folder: String) -> bool:
	return (
		DirAccess.dir_exists_absolute(folder)
		and not FileAccess.file_exists(folder.path_join("closed"))
	)


## The queue name of the range of chunks `first`..`last`.
static func range_name(first: int, last: int) -> String:
	return "r%05d-%05d" % [first, last]


## The chunk indices a range name (range_name()) stands for; empty for another name.
static func chunks_of(name: String) -> PackedInt32Array:
	var out := PackedInt32Array()
	var ends := name.trim_prefix("r").split("-")
	if not name.begins_with("r") or ends.size() != 2:
		return out
	if not ends[0].is_valid_int() or not ends[1].is_valid_int():
		return out
	for c in range(int(ends[0]), int(ends[1]) + 1):
		out.append(c)
	return out


# True while there may be work: the folder is there, not closed, and the parent lives (on
# systems with /proc; elsewhere a parent that is gone leaves the folder, and the editor's
# dock or the command line cancels its workers itself).
static func _wanted(folder: String, parent_pid: int) -> bool:
	if not queue_open(folder):
		return false
	if parent_pid > 0 and DirAccess.dir_exists_absolute("/proc/self"):
		return DirAccess.dir_exists_absolute("/proc/%d" % parent_pid)
	return true


## Takes the first waiting range in `folder` for taker `id`: renames its todo file to the
## taker's took file. "" when none is waiting (or another taker won each one first).
static func take(folder: String, id: int) -> String:
	var files := DirAccess.get_files_at(folder)
	files.sort()
	for file in files:
		if not file.begins_with("todo_"):
			continue
		var name := file.trim_prefix("todo_")
		var took := folder.path_join("took_%d_%s" % [id, name])
		if DirAccess.rename_absolute(folder.path_join(file), took) == OK:
			return name
	return ""


# The test hook (FAULT_ENV): dies or hangs when it names this worker.
static func _fault(id: int, folder: String, parent_pid: int) -> void:
	var fault := OS.get_environment(FAULT_ENV)
	if fault == "die:%d" % id:
		OS.kill(OS.get_process_id())
	if fault == "hang:%d" % id:
		while _wanted(folder, parent_pid):
			OS.delay_msec(IDLE_MS * 5)


static func _text(path: String) -> String:
	return FileAccess.get_file_as_string(path) if FileAccess.file_exists(path) else ""
