class_name AnalysisWorker
extends PachinkoAnalysis
## A pachinko play analysis run in a worker process instead of this one: the game binary,
## headless, on the board written to a file (`--analyze=pachinko --tally=FILE`, see
## analyze_cli.gd), on `plan.threads` threads of its own. The editor's Analyze uses it, so
## the run goes at the speed of the command line, whatever the editor is drawing, and
## the editor never waits on it. Same interface as PachinkoAnalysis: start(), then poll()
## each frame; progress(), tally() (the worker's counts so far, read from the file it
## replaces as chunks finish), cancel() (kills the process). The figures are the ones the
## same plan gives in this process for the board as its file holds it: the worker reads
## the board back from its file text (BoardTextWriter, coordinates to 0.01 px, the text the
## AnalysisCache key is made of) and runs the same plan.
##
## A worker that cannot start, or stops without its counts (a board its loader refuses, a
## crash), ends the run with `failure` set and phase CANCELLED; the caller may then run
## the plan here instead. Only the contact-free plan with the bonus parts shut (the
## editor's) is run this way.

## Where the board files and counts of running workers are kept (removed when a run ends).
const FOLDER := "user://analysis_worker"
## The worker's files are looked at no more often than this, ms.
const POLL_MS := 100

## Why the worker failed ("" while it runs or once it finished).
var failure := ""

var _pid := -1
var _board_path := ""
var _tally_path := ""
var _counts: AnalysisTally
var _status := {}
var _last_look := -POLL_MS
var _worker_started := 0


## True when this process can start a worker: a desktop build with its executable.
static func available() -> bool:
	return (
		not OS.has_feature("web")
		and not OS.has_feature("mobile")
		and FileAccess.file_exists(OS.get_executable_path())
	)


## The command-line arguments a worker runs the plan with, reading the board from
## `board_path` and writing its counts to `tally_path` (both absolute or user:// paths).
static func arguments(
	run_plan: AnalysisPlan, board_path: String, tally_path: String
) -> PackedStringArray:
	return PackedStringArray(
		[
			"--headless",
			"--path",
			ProjectSettings.globalize_path("res://"),
			"--",
			"--analyze=pachinko",
			"--board=%s" % board_path,
			"--shots=%d" % run_plan.shots,
			"--seed=%d" % run_plan.rng_seed,
			"--threads=%d" % clampi(run_plan.threads, 1, 64),
			"--tally=%s" % tally_path,
		]
	)


## The worker process's id (-1 before it starts); the tests look for it once it is gone.
func process_id() -> int:
	return _pid


## Starts the worker process. False (with `failure` set) when the plan cannot run this way
## or the process does not start.
func start() -> bool:
	var problem := plan.problem()
	if problem.is_empty() and (plan.played or plan.bonus_open):
		problem = "a worker runs only the contact-free plan with the bonus parts shut"
	if problem.is_empty() and (plan.power_from != 0.0 or plan.power_to != 100.0):
		problem = "a worker runs only the whole power range"
	if not problem.is_empty():
		failure = problem
		return false
	var made := DirAccess.make_dir_recursive_absolute(ProjectSettings.globalize_path(FOLDER))
	var stem := "%d_%d" % [OS.get_process_id(), Time.get_ticks_usec()]
	_board_path = FOLDER.path_join(stem + ".board")
	_tally_path = ProjectSettings.globalize_path(FOLDER.path_join(stem + ".tally"))
	var file := FileAccess.open(_board_path, FileAccess.WRITE) if made == OK else null
	if file == null:
		failure = "could not write %s" % _board_path
		return false
	file.store_string(BoardTextWriter.write(plan.level))
	file.close()
	_pid = OS.create_process(OS.get_executable_path(), arguments(plan, _board_path, _tally_path))
	if _pid <= 0:
		failure = "could not start %s" % OS.get_executable_path()
		_remove_files()
		return false
	_worker_started = Time.get_ticks_usec()
	phase = Phase.CLIMBS
	return true


## Blocking run (tests): starts the worker and waits for its counts; null when it failed.
func run() -> AnalysisTally:
	if not start():
		return null
	while not poll():
		OS.delay_msec(POLL_MS)
	return _counts if phase == Phase.DONE else null


## Looks at the worker's files (at most every POLL_MS); true once it is done, failed or
## cancelled. Never waits.
func poll() -> bool:
	if phase == Phase.DONE or phase == Phase.CANCELLED or phase == Phase.IDLE:
		return phase != Phase.IDLE
	if Time.get_ticks_msec() - _last_look < POLL_MS:
		return false
	_last_look = Time.get_ticks_msec()
	var running := OS.is_process_running(_pid)
	if FileAccess.file_exists(_tally_path):
		var counts := AnalysisTally.from_bytes(FileAccess.get_file_as_bytes(_tally_path))
		if counts != null:
			_counts = counts
			wall_seconds = (Time.get_ticks_usec() - _worker_started) / 1e6
			phase = Phase.DONE
			_remove_files()
			return true
	_read_status()
	_read_part()
	if not running:
		var code := OS.get_process_exit_code(_pid)
		failure = "the worker process stopped (exit code %d) before it finished" % code
		phase = Phase.CANCELLED
		_remove_files()
		return true
	return false


## Stops the worker (kills its process); poll() then reports done with phase CANCELLED.
## The counts read so far stay.
func cancel() -> void:
	if phase == Phase.CLIMBS or phase == Phase.SHOTS:
		if _pid > 0 and OS.is_process_running(_pid):
			OS.kill(_pid)
		phase = Phase.CANCELLED
		_remove_files()


## Share of the shots done, 0..1 (as the worker last said).
func progress() -> float:
	if phase == Phase.DONE:
		return 1.0
	var said: float = _status.get("shots_done", 0.0)
	return said / maxf(plan.shots, 1)


## Share of the rail climbs done, 0..1 (as the worker last said).
func climb_progress() -> float:
	if phase == Phase.DONE or phase == Phase.SHOTS:
		return 1.0
	var share: float = _status.get("climbs", 0.0)
	return share


## The worker's counts so far (all of them once done); null before any chunk finished.
func tally() -> AnalysisTally:
	return _counts


func _read_status() -> void:
	var path := _tally_path + ".status"
	if not FileAccess.file_exists(path):
		return
	var parsed: Variant = JSON.parse_string(FileAccess.get_file_as_string(path))
	if parsed is Dictionary:
		_status = parsed
		if _status.get("phase", "") == "shots":
			phase = Phase.SHOTS


# Reads the counts so far when the worker's status says it has more than were read.
func _read_part() -> void:
	var path := _tally_path + ".part"
	var said: int = _status.get("shots_done", 0)
	if said <= (_counts.total_shots() if _counts != null else 0):
		return
	if not FileAccess.file_exists(path):
		return
	var counts := AnalysisTally.from_bytes(FileAccess.get_file_as_bytes(path))
	if counts != null:
		_counts = counts


func _remove_files() -> void:
	var paths: Array[String] = [
		ProjectSettings.globalize_path(_board_path),
		_tally_path,
		_tally_path + ".status",
		_tally_path + ".part",
		_tally_path + ".tmp",
		_tally_path + ".status.tmp",
		_tally_path + ".part.tmp",
	]
	for path: String in paths:
		if not path.is_empty() and FileAccess.file_exists(path):
			DirAccess.remove_absolute(path)
