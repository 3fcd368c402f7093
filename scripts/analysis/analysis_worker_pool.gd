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
## Why the pool could not start ("" when it did).
var failure := ""
## What went wrong with workers during the run, one line each (also printed on stderr).
var incidents := PackedStringArray()

var _folder := ""
var _pids := PackedInt32Array()
var _beats := PackedStringArray()
var _beat_at := PackedInt64Array()
var _names := PackedStringArray()
var _counts: Array[AnalysisTally] = []
var _open_counts: Array[AnalysisTally] = []
var _ranges_done := 0
var _last_look := -POLL_MS
var _here: PachinkoAnalysis = null
var _here_open: PachinkoAnalysis = null
var _here_ranges := PackedInt32Array()
var _merged: AnalysisTally = null
var _merged_open: AnalysisTally = null


## Worker processes a run uses by default: every core when there are more than two (two
## worker processes on two cores lost to two threads: see scripts/analysis/README.md), else
## none (0: threads in this process).
static func default_workers() -> int:
	var cores := OS.get_processor_count()
	return cores if cores > 2 else 0


## Removes the queue folders in `root` left by runs whose process is gone (a command line
## that was killed cannot clean up; its workers exit by themselves). Only where /proc tells
## which processes live; the folders are named `PID_USEC.queue`.
static func remove_stale_queues(root: String) -> void:
	if not DirAccess.dir_exists_absolute("/proc/self"):
		return
	for entry in DirAccess.get_directories_at(root):
		var owner := entry.get_slice("_", 0)
		if not entry.ends_with(".queue") or not owner.is_valid_int():
			continue
		if DirAccess.dir_exists_absolute("/proc/%s" % owner):
			continue
		var stale := root.path_join(entry)
		for file in DirAccess.get_files_at(stale):
			DirAccess.remove_absolute(stale.path_join(file))
		DirAccess.remove_absolute(stale)


## The process ids of the workers started (-1 for those known to be gone).
func process_ids() -> PackedInt32Array:
	return _pids


## Starts the workers. False (with `failure` set) when the plan cannot run this way or no
## worker starts.
func start() -> bool:
	failure = _start_problem()
	if failure.is_empty():
		_started_usec = Time.get_ticks_usec()
		failure = _write_queue()
	if not failure.is_empty():
		_remove_folder()
		return false
	var board := board_path
	if board.is_empty():
		board = AnalysisWorker.FOLDER.path_join(_folder.get_file()).path_join("board.board")
	for k in mini(workers, _names.size()):
		var pid := OS.create_process(
			OS.get_executable_path(), _program_prefix() + _arguments(board, k)
		)
		_pids.append(pid if pid > 0 else -1)
		_beats.append("")
		_beat_at.append(Time.get_ticks_msec())
	if _pids.count(-1) == _pids.size():
		failure = "could not start %s" % OS.get_executable_path()
		_remove_folder()
		return false
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
	if Time.get_ticks_msec() - _last_look < POLL_MS:
		return false
	_last_look = Time.get_ticks_msec()
	var files := DirAccess.get_files_at(_folder)
	_take_results(files)
	for k in _pids.size():
		_watch(k, files)
	if _ranges_done == _names.size():
		_finish()
		return true
	if _pids.count(-1) == _pids.size():
		_run_rest_here()
	return false


## Kills every worker (and stops the run here, if any); poll() then reports done with phase
## CANCELLED. The counts taken in so far stay.
func cancel() -> void:
	if phase != Phase.SHOTS:
		return
	_stop_workers()
	if _here != null:
		_here.cancel()
		_here_open = null
	phase = Phase.CANCELLED
	_remove_folder()


## Share of the shots done, 0..1.
func progress() -> float:
	if phase == Phase.DONE:
		return 1.0
	var here := 0.0
	if _here != null:
		var share := _here.progress() if _here_open == null else 1.0 + _here_open.progress()
		here = share / (2.0 if with_open else 1.0) * _here_ranges.size()
	return (_ranges_done + here) / maxf(_names.size(), 1)


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
		OS.delay_msec(POLL_MS if _here == null else 5)
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


# Makes the queue folder with the board (unless board_path names one), the job and a todo
# file per range; "" or what failed.
func _write_queue() -> String:
	var root := ProjectSettings.globalize_path(AnalysisWorker.FOLDER)
	remove_stale_queues(root)
	_folder = root.path_join("%d_%d.queue" % [OS.get_process_id(), Time.get_ticks_usec()])
	if DirAccess.make_dir_recursive_absolute(_folder) != OK:
		return "could not make %s" % _folder
	if board_path.is_empty():
		var text := BoardTextWriter.write(plan.level).to_utf8_buffer()
		if SafeWrite.write_bytes(_folder.path_join("board.board"), text) != OK:
			return "could not write the board in %s" % _folder
	var job := {"parent": OS.get_process_id(), "with_open": with_open}
	if (
		SafeWrite.write_bytes(_folder.path_join("job.json"), JSON.stringify(job).to_utf8_buffer())
		!= OK
	):
		return "could not write the job in %s" % _folder
	for first in range(0, plan.chunk_count(), RANGE_CHUNKS):
		var last := mini(first + RANGE_CHUNKS, plan.chunk_count()) - 1
		var name := AnalysisQueueWorker.range_name(first, last)
		_names.append(name)
		if SafeWrite.write_bytes(_folder.path_join("todo_" + name), PackedByteArray()) != OK:
			return "could not write the queue in %s" % _folder
	_counts.resize(_names.size())
	_open_counts.resize(_names.size())
	return ""


## What goes before a worker's own arguments. In the release folder this process is the
## bundled loader named like the game (engine/board-studio, beside board-studio.pck and the
## engine binary `godot`), so a worker is the same loader given the libraries and the engine;
## the loader runs the engine in its own process, so the pid it gets can still be killed.
static func _program_prefix() -> PackedStringArray:
	var exe := OS.get_executable_path()
	var folder := exe.get_base_dir()
	var engine := folder.path_join("godot")
	var pack := exe.get_basename() + ".pck"
	if (
		exe.get_file() != "godot"
		and FileAccess.file_exists(engine)
		and FileAccess.file_exists(pack)
	):
		return PackedStringArray(["--library-path", folder.path_join("lib"), engine])
	return PackedStringArray()


func _arguments(board: String, id: int) -> PackedStringArray:
	var args := PackedStringArray(["--headless", "--quiet"])
	# The editor build runs the project folder; an exported game loads the pack beside its
	# binary by itself, and a release template refuses --path.
	if OS.has_feature("editor"):
		args.append_array(PackedStringArray(["--path", ProjectSettings.globalize_path("res://")]))
	(
		args
		. append_array(
			[
				"--",
				"--analyze=pachinko",
				"--board=%s" % board,
				"--shots=%d" % plan.shots,
				"--seed=%d" % plan.rng_seed,
				"--queue=%s" % _folder,
				"--worker-id=%d" % id,
			]
		)
	)
	if plan.played:
		args.append("--played")
	return args


# Takes in the counts of every range whose files are there.
func _take_results(files: PackedStringArray) -> void:
	for r in _names.size():
		if _counts[r] != null:
			continue
		var shut := "done_%s.tally" % _names[r]
		var open := "done_%s.open.tally" % _names[r]
		if not files.has(shut) or (with_open and not files.has(open)):
			continue
		var counts := AnalysisTally.from_bytes(
			FileAccess.get_file_as_bytes(_folder.path_join(shut))
		)
		var open_counts: AnalysisTally = null
		if with_open:
			open_counts = AnalysisTally.from_bytes(
				FileAccess.get_file_as_bytes(_folder.path_join(open))
			)
		if counts == null or (with_open and open_counts == null):
			_report(
				"the counts of chunks %s could not be read; running them again" % _chunks_text(r)
			)
			DirAccess.remove_absolute(_folder.path_join(shut))
			SafeWrite.write_bytes(_folder.path_join("todo_" + _names[r]), PackedByteArray())
			continue
		_counts[r] = counts
		_open_counts[r] = open_counts
		_ranges_done += 1


# Worker `k`: notes its progress; a worker that stopped, or hangs, holding ranges is
# reported and its ranges go back in the queue.
func _watch(k: int, files: PackedStringArray) -> void:
	if _pids[k] < 0:
		return
	var held := _held(k, files)
	var beat_path := _folder.path_join("beat_%d" % k)
	var beat := FileAccess.get_file_as_string(beat_path) if files.has(beat_path.get_file()) else ""
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
						% [k, _pids[k], code, _held_text(held)]
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
					% [k, _pids[k], roundi(hang_seconds), _held_text(held)]
				)
				+ " killed, running them again"
			)
		)
		OS.kill(_pids[k])
		_pids[k] = -1
	else:
		return
	for r in held:
		DirAccess.rename_absolute(
			_folder.path_join("took_%d_%s" % [k, _names[r]]), _folder.path_join("todo_" + _names[r])
		)


# The ranges worker `k` took and has not finished.
func _held(k: int, files: PackedStringArray) -> PackedInt32Array:
	var out := PackedInt32Array()
	var prefix := "took_%d_" % k
	for file in files:
		if file.begins_with(prefix):
			var r := _names.find(file.trim_prefix(prefix))
			if r >= 0 and _counts[r] == null:
				out.append(r)
	return out


func _held_text(held: PackedInt32Array) -> String:
	var parts := PackedStringArray()
	for r in held:
		parts.append(_chunks_text(r))
	return ", ".join(parts)


func _chunks_text(r: int) -> String:
	var chunks := AnalysisQueueWorker.chunks_of(_names[r])
	if chunks.size() == 1:
		return str(chunks[0])
	return "%d-%d" % [chunks[0], chunks[chunks.size() - 1]]


func _report(line: String) -> void:
	incidents.append(line)
	printerr("analysis: %s" % line)


# No worker is left: the ranges not done run here, on plan.threads threads.
func _run_rest_here() -> void:
	var chunks := PackedInt32Array()
	for r in _names.size():
		if _counts[r] == null:
			_here_ranges.append(r)
			chunks.append_array(AnalysisQueueWorker.chunks_of(_names[r]))
	_report("no worker left; running chunks %s here" % _held_text(_here_ranges))
	_here = PachinkoAnalysis.new(plan)
	_here.only_chunks = chunks
	if not _here.start():
		_here = null
		phase = Phase.CANCELLED
		_remove_folder()


func _poll_here() -> bool:
	if not _here.poll():
		return false
	if _here.phase != Phase.DONE:
		phase = Phase.CANCELLED
		_remove_folder()
		return true
	if with_open and _here_open == null:
		_here_open = PachinkoAnalysis.new(plan.with_bonus_open())
		_here_open.only_chunks = _here.only_chunks
		_here_open.reuse_climbs(_here.climb_table())
		if _here_open.start():
			return false
		phase = Phase.CANCELLED
		_remove_folder()
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
	SafeWrite.write_bytes(_folder.path_join("closed"), PackedByteArray())
	_remove_folder()
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


func _remove_folder() -> void:
	if _folder.is_empty() or not DirAccess.dir_exists_absolute(_folder):
		return
	for file in DirAccess.get_files_at(_folder):
		DirAccess.remove_absolute(_folder.path_join(file))
	DirAccess.remove_absolute(_folder)
