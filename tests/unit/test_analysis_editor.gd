extends GutTest
## The editor's play-analysis section driven headless: a background run that finishes and
## is cached, a cached result shown for the same content and dropped after an edit, cancel.

const AnalysisPanel := preload("res://addons/board_editor/analysis/analysis_panel.gd")
const TEST_FOLDER := "user://test_analysis_editor"

var _saved_folder := ""


func before_each() -> void:
	_saved_folder = AnalysisCache.folder_override
	AnalysisCache.folder_override = TEST_FOLDER


func after_each() -> void:
	if DirAccess.dir_exists_absolute(TEST_FOLDER):
		for file in DirAccess.get_files_at(TEST_FOLDER):
			DirAccess.remove_absolute(TEST_FOLDER.path_join(file))
	AnalysisCache.folder_override = _saved_folder


func _panel() -> AnalysisPanel:
	var panel := AnalysisPanel.new()
	panel.shots = 260
	add_child_autofree(panel)
	return panel


func _classic() -> BoardLevel:
	return BoardLoader.load_board("res://levels/pachinko/classic.board").level


# Lets the panel poll its run the way the editor's frames would.
func _finish(panel: AnalysisPanel) -> void:
	var started := Time.get_ticks_msec()
	while panel.is_running() and Time.get_ticks_msec() - started < 60000:
		panel._process(0.016)
		OS.delay_msec(10)


func test_a_run_shows_figures_and_caches_them_per_board_content() -> void:
	var level := _classic()
	var panel := _panel()
	panel.bind(level)
	assert_true(panel.report().is_empty(), "nothing analysed yet")
	panel.start()
	assert_true(panel.is_running(), "runs in the background")
	_finish(panel)
	assert_false(panel.is_running())
	assert_eq(panel.report().get("shots"), 260)
	# Another panel (a reopened board) with the same content shows it from the cache.
	var reopened := _panel()
	reopened.bind(level.duplicate_level())
	assert_eq(reopened.report().get("shots"), 260.0)
	# An edit makes it stale.
	level.pins[3] += Vector2(0, 2)
	level.notify_edited()
	reopened.bind(level)
	assert_true(reopened.report().is_empty(), "edited board: the old figures are gone")


func test_the_worker_process_gives_the_figures_of_a_run_in_the_editor() -> void:
	if not AnalysisWorker.available():
		pass_test("no worker process on this platform")
		return
	var figures: Array[Dictionary] = []
	for worker: bool in [true, false]:
		AnalysisCache.folder_override = TEST_FOLDER + ("_w" if worker else "_e")
		var panel := _panel()
		panel.use_worker = worker
		panel.worker_processes = 0
		panel.bind(_classic())
		panel.start()
		assert_eq(panel._run is AnalysisWorker, worker, "worker: %s" % worker)
		_finish(panel)
		var report := panel.report().duplicate(true)
		for key: String in ["wall_s", "shots_per_s"]:
			report.erase(key)
		figures.append(report)
		for file in DirAccess.get_files_at(AnalysisCache.folder()):
			DirAccess.remove_absolute(AnalysisCache.folder().path_join(file))
	assert_eq(figures[0].get("shots"), 260)
	assert_eq(JSON.stringify(figures[0]), JSON.stringify(figures[1]), "the same figures")


func test_worker_processes_give_the_figures_of_a_run_in_the_editor() -> void:
	if not AnalysisWorker.available():
		pass_test("no worker process on this platform")
		return
	var figures: Array[Dictionary] = []
	for workers: int in [2, 0]:
		AnalysisCache.folder_override = TEST_FOLDER + "_p%d" % workers
		var panel := _panel()
		panel.worker_processes = workers
		panel.bind(_classic())
		panel.start()
		assert_eq(panel.running() is AnalysisWorkerPool, workers > 0, "workers: %d" % workers)
		_finish(panel)
		var report := panel.report().duplicate(true)
		for key: String in ["wall_s", "shots_per_s"]:
			report.erase(key)
		figures.append(report)
		for file in DirAccess.get_files_at(AnalysisCache.folder()):
			DirAccess.remove_absolute(AnalysisCache.folder().path_join(file))
	assert_eq(figures[0].get("shots"), 260)
	assert_eq(JSON.stringify(figures[0]), JSON.stringify(figures[1]), "the same figures")


func test_cancel_keeps_the_editor_usable() -> void:
	var panel := _panel()
	panel.shots = 5000
	panel.bind(_classic())
	panel.start()
	panel.cancel()
	_finish(panel)
	assert_false(panel.is_running())
	assert_string_contains(panel._controls.status.text, "Cancelled")
	panel.bind(panel._level)  # the plugin binds again after every change of the results
	assert_string_contains(panel._controls.status.text, "Cancelled", "the status stays")
	assert_true(
		AnalysisCache.load_report(AnalysisCache.key_for(panel._plan_for(panel._level))).is_empty(),
		"a cancelled run is not cached"
	)


func test_a_maze_board_hides_the_section() -> void:
	var panel := _panel()
	panel.bind(BoardLoader.load_board("res://levels/maze/classic.board").level)
	assert_false(panel.visible)
	panel.start()
	assert_false(panel.is_running())
