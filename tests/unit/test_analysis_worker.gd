extends GutTest
## The editor's analysis in a worker process (AnalysisWorker): the game binary headless
## gives the counts this process gives for the same plan, cancel stops it, a board it
## cannot load fails the run with a reason; and the counts survive their bytes.


func _classic() -> BoardLevel:
	return BoardLoader.load_board("res://levels/pachinko/classic.board").level


func test_a_worker_counts_what_this_process_counts() -> void:
	var plan := AnalysisPlan.create(_classic(), 500, 7)
	plan.threads = 2
	var here := PachinkoAnalysis.new(plan).run()
	var worker := AnalysisWorker.new(plan)
	var there := worker.run()
	assert_eq(worker.failure, "", "the worker finished")
	assert_not_null(there, "the worker's counts came back")
	if there == null:
		return
	assert_eq(worker.phase, PachinkoAnalysis.Phase.DONE)
	var a := AnalysisReport.build(plan, here, 1.0)
	var b := AnalysisReport.build(plan, there, 1.0)
	assert_eq(JSON.stringify(b), JSON.stringify(a), "the same report")
	assert_eq(there.density, here.density, "the same heat map")
	assert_eq(there.ball_steps, here.ball_steps)
	assert_eq(worker.progress(), 1.0)
	var left := DirAccess.get_files_at(AnalysisWorker.FOLDER)
	assert_eq(
		Array(left).filter(
			func(f: String) -> bool: return f.begins_with(str(OS.get_process_id()) + "_")
		),
		[],
		"its files are removed"
	)


func test_cancel_kills_the_worker() -> void:
	var worker := AnalysisWorker.new(AnalysisPlan.create(_classic(), 10000, 1))
	assert_true(worker.start())
	OS.delay_msec(300)
	assert_false(worker.poll(), "still running")
	worker.cancel()
	assert_true(worker.poll(), "done once cancelled")
	assert_eq(worker.phase, PachinkoAnalysis.Phase.CANCELLED)
	OS.delay_msec(200)
	if DirAccess.dir_exists_absolute("/proc/self"):
		var pid := worker.process_id()
		assert_false(DirAccess.dir_exists_absolute("/proc/%d" % pid), "the process is gone")


func test_a_board_the_worker_cannot_load_fails_the_run_with_a_reason() -> void:
	var broken := _classic().duplicate_level()
	broken.ring_radius = -5.0  # the loader refuses it; this process's plan would too
	var worker := AnalysisWorker.new(AnalysisPlan.create(broken, 100, 1))
	assert_null(worker.run())
	assert_ne(worker.failure, "", "it says why")
	var played := AnalysisPlan.create(_classic(), 100, 1)
	played.played = true
	var refused := AnalysisWorker.new(played)
	assert_false(refused.start(), "a played plan is not run in a worker")
	assert_string_contains(refused.failure, "contact-free")


func test_counts_survive_their_bytes() -> void:
	var plan := AnalysisPlan.create(_classic(), 250, 2)
	var tally := PachinkoAnalysis.new(plan).run()
	var back := AnalysisTally.from_bytes(tally.to_bytes())
	assert_not_null(back)
	for key: String in AnalysisTally.SAVED_ARRAYS:
		assert_eq(back.get(key), tally.get(key), key)
	assert_eq(back.ball_steps, tally.ball_steps)
	assert_eq(back.grid_size, tally.grid_size)
	assert_null(AnalysisTally.from_bytes(var_to_bytes("text")), "not a tally")
	assert_null(AnalysisTally.from_bytes(var_to_bytes({"density": 3})), "not a tally")
