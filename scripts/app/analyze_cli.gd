class_name AnalyzeCli
extends RefCounted
## The `--analyze` command: a play analysis of one board, headless. Pachinko fires
## `--shots` shots (AnalysisPlan); the maze plays `--runs` autoplay games in easy and hard
## mode (MazeAnalysis). Prints one JSON line and writes it, with a heat-map PNG for
## pachinko, to <folder>/<game>_<board>.json, and says on stderr where. The folder is
## `--out` (relative to the folder the command runs in); without it, build/analysis/ in the
## project when run from the project, and the player's own data folder (beside their
## settings, user://reports/) in the exported game. command_line.gd hands it the flags.

## A board that cannot be loaded is bad input, like a bad flag (cli_flags.gd EXIT_USAGE).
const EXIT_BAD_INPUT := 2
const EXIT_FAILED := 1
## Where the reports go when run from the project, relative to the project folder.
const OUT_DIR := "build/analysis"
## Where they go in the exported game: the player's data folder.
const PLAYER_OUT_DIR := "user://reports"
## Another folder for tests ("" uses OUT_DIR; a static initialiser would not run in the
## editor for a script that is not @tool).
static var out_dir_override := ""


## Runs the analysis `values` ask for (keys analyze, board, shots, runs, seed, threads,
## workers, and the worker modes' tally, queue, worker_id); returns the exit code. Pachinko
## runs on `workers` worker processes (AnalysisWorkerPool; default: one per core on more
## than two cores), else on `threads` threads here (PachinkoAnalyzeCli makes its report).
static func run(values: Dictionary) -> int:
	var game: String = values["analyze"]
	var rng_seed: int = values["seed"]
	var board_name := str(values["board"])
	var queue := str(values.get("queue", ""))
	if not queue.is_empty() and not AnalysisQueueWorker.queue_open(queue):
		return 0  # a worker started after its run ended: nothing left to do
	var roots := BoardLoader.BOARD_ROOTS.duplicate()
	if not str(values.get("tally", "")).is_empty() or not str(values.get("queue", "")).is_empty():
		roots.append(AnalysisWorker.FOLDER + "/")  # the editor's workers read its board there
	var loaded := BoardLoader.load_board(AutoplayCli.resolve_board_path(game, board_name), roots)
	if loaded.level == null:
		return _fail(EXIT_BAD_INPUT, loaded.error)
	var threads: int = values.get("threads", OS.get_processor_count())
	if threads < 1 or threads > 64:
		return _fail(EXIT_BAD_INPUT, "--threads must be 1 to 64 (got %d)" % threads)
	var name := "%s_%s" % [game, board_name.get_file().get_basename()]
	var folder := _out_folder(str(values.get("out", "")))
	if folder.has("error"):
		return _fail(EXIT_BAD_INPUT, str(folder["error"]))
	var base := str(folder["shown"]).path_join(name)
	var abs_base := str(folder["dir"]).path_join(name)
	var report: Dictionary
	if game == BoardLevel.MAZE_NAME:
		var runs: int = values.get("runs", MazeAnalysis.DEFAULT_RUNS)
		if runs < 1:
			return _fail(EXIT_BAD_INPUT, "--runs must be at least 1 (got %d)" % runs)
		report = MazeAnalysis.run(loaded.level, runs, rng_seed, threads)
		if report.has("error"):
			return _fail(EXIT_BAD_INPUT, str(report["error"]))
	else:
		var shots: int = values.get("shots", 10000)
		if shots < 1:
			return _fail(EXIT_BAD_INPUT, "--shots must be at least 1 (got %d)" % shots)
		var plan := AnalysisPlan.create(loaded.level, shots, rng_seed)
		plan.threads = threads
		plan.played = values.get("played", false)
		if not str(values.get("tally", "")).is_empty():
			return _run_worker(plan, str(values["tally"]))
		if not str(values.get("queue", "")).is_empty():
			var worker_id: int = values.get("worker_id", 0)
			return AnalysisQueueWorker.run(plan, str(values["queue"]), worker_id)
		report = PachinkoAnalyzeCli.report(
			plan, values, AutoplayCli.resolve_board_path(game, board_name), base, abs_base
		)
		if report.has("error"):
			var code := EXIT_FAILED if report.get("unwritten", false) else EXIT_BAD_INPUT
			return _fail(code, str(report["error"]))
	report["ok"] = true
	report["report"] = base + ".json"
	var text := JSON.stringify(report)
	var file := FileAccess.open(abs_base + ".json", FileAccess.WRITE)
	if file == null:
		return _fail(EXIT_FAILED, "could not write %s.json" % base)
	file.store_line(text)
	file.close()
	print(text)
	printerr("analyze: report written to %s.json" % abs_base)
	return 0


# The folder the command was typed in: the shell's PWD (Godot itself moves into the project
# folder when given --path), else the process's own.
static func _invoking_folder() -> String:
	var typed_in := OS.get_environment("PWD")
	if typed_in.is_absolute_path() and DirAccess.dir_exists_absolute(typed_in):
		return typed_in
	return DirAccess.open(".").get_current_dir()


# Worker mode (`--tally=FILE`, AnalysisWorker): runs the plan and writes only its counts,
# FILE (AnalysisTally.to_bytes()) at the end; meanwhile FILE.status (JSON: phase, climbs
# 0..1, shots_done, shots) and FILE.part (the counts of the chunks done so far) as they
# change, each replaced whole (written aside, then renamed), so a reader never sees half.
static func _run_worker(plan: AnalysisPlan, path: String) -> int:
	var analysis := PachinkoAnalysis.new(plan)
	if not analysis.start():
		return _fail(EXIT_BAD_INPUT, plan.problem())
	var last_status := ""
	var last_chunks := 0.0
	var shots_done := 0
	while true:
		var done := analysis.poll()
		var chunks := analysis.progress()
		if chunks != last_chunks or done:
			last_chunks = chunks
			var part := analysis.tally()
			if part != null:
				shots_done = part.total_shots()
				if not done and SafeWrite.write_bytes(path + ".part", part.to_bytes()) != OK:
					return _fail(EXIT_FAILED, "could not write %s.part" % path)
		var phase_name: String = PachinkoAnalysis.Phase.keys()[analysis.phase]
		var status := {
			"phase": "done" if done else phase_name.to_lower(),
			"climbs": snappedf(analysis.climb_progress(), 0.001),
			"shots_done": shots_done,
			"shots": plan.shots,
		}
		var text := JSON.stringify(status)
		if text != last_status:
			last_status = text
			SafeWrite.write_bytes(path + ".status", text.to_utf8_buffer())
		if done:
			break
		OS.delay_msec(50)
	var tally := analysis.tally()
	if tally == null or SafeWrite.write_bytes(path, tally.to_bytes()) != OK:
		return _fail(EXIT_FAILED, "could not write %s" % path)
	var line := {"ok": true, "tally": path, "shots": tally.total_shots()}
	line["wall_s"] = snappedf(analysis.wall_seconds, 0.001)
	print(JSON.stringify(line))
	return 0


# The folder the reports go to, made when missing: {"dir": its absolute path, "shown": how
# the report names it (relative to the project when run from it)}, or {"error": why not}.
static func _out_folder(out_flag: String) -> Dictionary:
	var dir := ""
	var shown := ""
	if not out_flag.is_empty():
		dir = out_flag
		if dir.is_relative_path():
			dir = _invoking_folder().path_join(dir)
		shown = dir.simplify_path()
		dir = shown
	elif not out_dir_override.is_empty() or not OS.has_feature("template"):
		shown = out_dir_override if not out_dir_override.is_empty() else OUT_DIR
		dir = ProjectSettings.globalize_path("res://").path_join(shown)
	else:
		dir = ProjectSettings.globalize_path(PLAYER_OUT_DIR)
		shown = dir
	var made := DirAccess.make_dir_recursive_absolute(dir)
	if made != OK and not DirAccess.dir_exists_absolute(dir):
		return {
			"error": "cannot make the folder %s for the report (%s)" % [dir, error_string(made)]
		}
	return {"dir": dir, "shown": shown}


static func _fail(code: int, problem: String) -> int:
	printerr("analyze: %s" % problem)
	print(JSON.stringify({"ok": false, "error": problem}))
	return code
