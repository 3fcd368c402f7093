extends SceneTree
## `make bench`: the pachinko play analysis's speed, shots per second on Classic and Fever
## on one thread, on every core's thread, and on N worker processes (AnalysisWorkerPool,
## the `--workers` route of `--analyze` and of the editor on more than two cores: the game
## binary started headless N times, its start-up counted) (the contact-free plan of
## `--analyze` and the editor's Analyze, without the bonus-open second run), with where each
## in-process run's time went (AnalysisProfile: rail climbs, stepping, the rest) and the
## figures that must not move with the speed (return, ball-steps: every run's must equal
## one thread's, else the bench fails). Each figure is the best of ROUNDS runs, the runs of
## one board taken in turn (1 thread, all threads, workers, 1 thread, ...), so a busy moment
## costs one run, not a figure. Then the designer's Analyze as the editor runs it
## (AnalysisPlan.EDITOR_SHOTS shots): every core's threads against the worker processes,
## side by side in the same rounds. Writes build/bench/analysis.json.
##
## `-- --analysis-shots=N` changes the shots per run (default SHOTS); `--analysis-workers=N`
## the worker processes (default: one per core but this process's, at least 1; this process
## fires its share of the ranges beside them, AnalysisLocalShare).

const OUT_PATH := "res://build/bench/analysis.json"
const BOARDS: Array[String] = ["classic", "fever"]
## Shots per run: 8 chunks of 250 (Fever's take about 12 s on one thread here).
const SHOTS := 2000
const SEED := 1
## Runs per board and thread count; the fastest counts.
const ROUNDS := 3
## Runs per board and mode of the designer-sized side-by-side (AnalysisPlan.EDITOR_SHOTS
## shots: a worker's start, about a second, is paid back over a run this long).
const DESIGNER_ROUNDS := 2


func _initialize() -> void:
	# On the first frame: the worker pool's group tasks do not run before the main loop.
	process_frame.connect(_bench, CONNECT_ONE_SHOT)


func _bench() -> void:
	var shots := SHOTS
	var cores := OS.get_processor_count()
	var workers := maxi(cores - 1, 1)
	for arg in OS.get_cmdline_user_args():
		if arg.begins_with("--analysis-shots="):
			shots = maxi(int(arg.get_slice("=", 1)), 1)
		if arg.begins_with("--analysis-workers="):
			workers = clampi(int(arg.get_slice("=", 1)), 1, 64)
	# Each run: [threads, worker processes (0: threads in this process)].
	var modes: Array[Vector2i] = [Vector2i(1, 0)]
	if cores > 1:
		modes.append(Vector2i(cores, 0))
	# The designer's Analyze, side by side: every core's threads against the workers.
	var designer_modes: Array[Vector2i] = [Vector2i(cores, 0)]
	if AnalysisWorker.available():
		modes.append(Vector2i(1, workers))
		designer_modes.append(Vector2i(1, workers))
	var rows: Array[Dictionary] = []
	var designer_rows: Array[Dictionary] = []
	var started := Time.get_ticks_msec()
	for board in BOARDS:
		var loaded := BoardLoader.load_board("res://levels/pachinko/%s.board" % board)
		if loaded.level == null:
			printerr("bench_analysis: %s" % loaded.error)
			quit(1)
			return
		var best := _best_runs(board, loaded.level, shots, modes, ROUNDS)
		if best.is_empty():
			quit(1)
			return
		var designer := _best_runs(
			board, loaded.level, AnalysisPlan.EDITOR_SHOTS, designer_modes, DESIGNER_ROUNDS
		)
		if designer.is_empty():
			quit(1)
			return
		rows.append_array(best)
		designer_rows.append_array(designer)
	_print_table(rows, "Play analysis, %d shots (best of %d" % [shots, ROUNDS])
	_print_table(
		designer_rows,
		(
			"The designer's Analyze, %d shots: threads against workers (best of %d"
			% [AnalysisPlan.EDITOR_SHOTS, DESIGNER_ROUNDS]
		)
	)
	var out := {
		"shots": shots,
		"seed": SEED,
		"rounds": ROUNDS,
		"cores": cores,
		"workers": workers,
		"runs": rows,
		"designer_shots": AnalysisPlan.EDITOR_SHOTS,
		"designer_runs": designer_rows,
		"seconds": (Time.get_ticks_msec() - started) / 1000.0,
	}
	var path := ProjectSettings.globalize_path(OUT_PATH)
	DirAccess.make_dir_recursive_absolute(path.get_base_dir())
	var file := FileAccess.open(path, FileAccess.WRITE)
	if file == null:
		printerr("bench_analysis: could not write %s" % OUT_PATH)
		quit(1)
		return
	file.store_line(JSON.stringify(out, "  "))
	file.close()
	print("bench_analysis: wrote %s" % OUT_PATH)
	quit(0)


# The fastest of `rounds` runs of each mode on `level`, the modes taken in turn (so a busy
# moment costs one run, not a figure); each row's ball-steps and return checked against the
# first mode's (they must not move with the speed). [] after a failed run or a mismatch.
func _best_runs(
	board: String, level: BoardLevel, shots: int, modes: Array[Vector2i], rounds: int
) -> Array[Dictionary]:
	var best: Array[Dictionary] = []
	best.resize(modes.size())
	for round in rounds:
		for m in modes.size():
			var run := _run(level, shots, modes[m].x, modes[m].y)
			if run.is_empty():
				return []
			print(
				(
					"  %s, %d shots, %s, round %d: %.1f shots/s"
					% [board, shots, _mode_name(run), round + 1, run["shots_per_s"]]
				)
			)
			if best[m].is_empty() or run["shots_per_s"] > best[m]["shots_per_s"]:
				best[m] = run
	for row in best:
		row["board"] = board
		if row["ball_steps"] != best[0]["ball_steps"] or row["return"] != best[0]["return"]:
			printerr(
				(
					"bench_analysis: %s, %s: ball_steps %d, not %s's %d"
					% [
						board,
						_mode_name(row),
						row["ball_steps"],
						_mode_name(best[0]),
						best[0]["ball_steps"]
					]
				)
			)
			return []
	return best


# One analysis of `shots` shots on `level` with `threads` threads, profiled, here or on
# `workers` worker processes (not profiled: their stages are other processes'). {} with an
# error when the workers failed.
func _run(level: BoardLevel, shots: int, threads: int, workers: int) -> Dictionary:
	var plan := AnalysisPlan.create(level, shots, SEED)
	plan.threads = threads
	var worker := workers > 0
	var analysis := PachinkoAnalysis.new(plan)
	if worker:
		var pool := AnalysisWorkerPool.new(plan)
		pool.workers = workers
		analysis = pool
	else:
		analysis.profile = AnalysisProfile.new()
	var tally := analysis.run()
	if tally == null or (worker and not (analysis as AnalysisWorkerPool).incidents.is_empty()):
		var pool := analysis as AnalysisWorkerPool
		printerr("bench_analysis: the workers failed: %s %s" % [pool.failure, pool.incidents])
		return {}
	var report := AnalysisReport.build(plan, tally, analysis.wall_seconds)
	var profile := analysis.profile.to_dict() if not worker else {}
	return {
		"threads": threads,
		"worker": worker,
		"workers": workers,
		"shots_per_s": report["shots_per_s"],
		"wall_s": report["wall_s"],
		"return": report["return"],
		"ball_steps": tally.ball_steps,
		"climb_ball_steps": profile.get("climb_ball_steps", -1),
		"stage_seconds": profile.get("seconds", {}),
	}


static func _mode_name(run: Dictionary) -> String:
	if run["worker"]:
		return "this + %d worker process(es)" % run["workers"]
	return "%d thread(s)" % run["threads"]


func _print_table(rows: Array[Dictionary], title: String) -> void:
	print("")
	print(title + "; stage seconds summed over threads)")
	print(
		(
			"%-8s %-24s %9s %7s %7s %7s %7s %8s %11s"
			% [
				"board",
				"run",
				"shots/s",
				"wall s",
				"climb",
				"step",
				"other",
				"return",
				"ball_steps"
			]
		)
	)
	for row in rows:
		var s: Dictionary = row["stage_seconds"]
		var other := 0.0
		for stage: String in s:
			if stage != "climb" and stage != "step":
				other += float(s[stage])
		var stages := ["-", "-", "-"]
		if not s.is_empty():
			stages = ["%.2f" % s["climb"], "%.2f" % s["step"], "%.2f" % other]
		print(
			(
				"%-8s %-24s %9.1f %7.2f %7s %7s %7s %8.4f %11d"
				% [
					row["board"],
					_mode_name(row),
					row["shots_per_s"],
					row["wall_s"],
					stages[0],
					stages[1],
					stages[2],
					row["return"],
					row["ball_steps"],
				]
			)
		)
