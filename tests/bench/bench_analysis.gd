extends SceneTree
## `make bench`: the pachinko play analysis's speed, shots per second on Classic and Fever
## on one thread and on every core (the contact-free plan of `--analyze` and the editor's
## Analyze, without the bonus-open second run), with where each run's time went
## (AnalysisProfile: rail climbs, stepping, the rest) and the figures that must not move
## with the speed (return, ball-steps). Each figure is the best of ROUNDS runs, the runs of
## one board taken in turn (1 thread, all threads, 1 thread, ...), so a busy moment costs
## one run, not a figure. Writes build/bench/analysis.json.
##
## `-- --analysis-shots=N` changes the shots per run (default SHOTS).

const OUT_PATH := "res://build/bench/analysis.json"
const BOARDS: Array[String] = ["classic", "fever"]
## Shots per run: 8 chunks of 250 (Fever's take about 12 s on one thread here).
const SHOTS := 2000
const SEED := 1
## Runs per board and thread count; the fastest counts.
const ROUNDS := 3


func _initialize() -> void:
	# On the first frame: the worker pool's group tasks do not run before the main loop.
	process_frame.connect(_bench, CONNECT_ONE_SHOT)


func _bench() -> void:
	var shots := SHOTS
	for arg in OS.get_cmdline_user_args():
		if arg.begins_with("--analysis-shots="):
			shots = maxi(int(arg.get_slice("=", 1)), 1)
	var cores := OS.get_processor_count()
	var thread_counts: Array[int] = [1]
	if cores > 1:
		thread_counts.append(cores)
	var rows: Array[Dictionary] = []
	var started := Time.get_ticks_msec()
	for board in BOARDS:
		var loaded := BoardLoader.load_board("res://levels/pachinko/%s.board" % board)
		if loaded.level == null:
			printerr("bench_analysis: %s" % loaded.error)
			quit(1)
			return
		var best: Array[Dictionary] = []
		best.resize(thread_counts.size())
		for round in ROUNDS:
			for t in thread_counts.size():
				var run := _run(loaded.level, shots, thread_counts[t])
				print(
					(
						"  %s, %d thread(s), round %d: %.1f shots/s"
						% [board, thread_counts[t], round + 1, run["shots_per_s"]]
					)
				)
				if best[t].is_empty() or run["shots_per_s"] > best[t]["shots_per_s"]:
					best[t] = run
		for row in best:
			row["board"] = board
			rows.append(row)
	_print_table(rows)
	var out := {
		"shots": shots,
		"seed": SEED,
		"rounds": ROUNDS,
		"cores": cores,
		"runs": rows,
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


# One analysis of `shots` shots on `level` with `threads` threads, profiled.
func _run(level: BoardLevel, shots: int, threads: int) -> Dictionary:
	var plan := AnalysisPlan.create(level, shots, SEED)
	plan.threads = threads
	var analysis := PachinkoAnalysis.new(plan)
	analysis.profile = AnalysisProfile.new()
	var tally := analysis.run()
	var report := AnalysisReport.build(plan, tally, analysis.wall_seconds)
	var profile := analysis.profile.to_dict()
	return {
		"threads": threads,
		"shots_per_s": report["shots_per_s"],
		"wall_s": report["wall_s"],
		"return": report["return"],
		"ball_steps": tally.ball_steps,
		"climb_ball_steps": profile["climb_ball_steps"],
		"stage_seconds": profile["seconds"],
	}


func _print_table(rows: Array[Dictionary]) -> void:
	print("")
	print("Play analysis (best of %d; stage seconds summed over threads)" % ROUNDS)
	print(
		(
			"%-8s %7s %9s %7s %7s %7s %7s %8s %11s"
			% [
				"board",
				"threads",
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
		print(
			(
				"%-8s %7d %9.1f %7.2f %7.2f %7.2f %7.2f %8.4f %11d"
				% [
					row["board"],
					row["threads"],
					row["shots_per_s"],
					row["wall_s"],
					s["climb"],
					s["step"],
					other,
					row["return"],
					row["ball_steps"],
				]
			)
		)
