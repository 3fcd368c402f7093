extends GutTest
## Honest progress: a play analysis's bar moves from the first work done (the rail climbs
## of a pachinko run, the first second of a maze game), and the status says how far it is
## and about how long it has left.

const RunProgress := preload("res://addons/board_editor/analysis/run_progress.gd")
const AnalysisPanel := preload("res://addons/board_editor/analysis/analysis_panel.gd")
const TEST_FOLDER := "user://test_analysis_progress"

var _saved_folder := ""


func before_each() -> void:
	_saved_folder = AnalysisCache.folder_override
	AnalysisCache.folder_override = TEST_FOLDER


func after_each() -> void:
	if DirAccess.dir_exists_absolute(TEST_FOLDER):
		for file in DirAccess.get_files_at(TEST_FOLDER):
			DirAccess.remove_absolute(TEST_FOLDER.path_join(file))
	AnalysisCache.folder_override = _saved_folder


func test_the_climbs_count_toward_the_run() -> void:
	assert_gt(RunProgress.pachinko_share(0.02, 0.0), 0.0, "the first climbs move the bar")
	assert_almost_eq(RunProgress.pachinko_share(1.0, 0.0), RunProgress.CLIMB_SHARE, 1e-6)
	assert_eq(RunProgress.pachinko_share(1.0, 1.0), 1.0)


func test_the_time_left_and_its_words() -> void:
	assert_eq(RunProgress.seconds_left(0.25, 10.0), 30.0, "a quarter in 10 s: 30 s to go")
	assert_eq(RunProgress.seconds_left(0.005, 10.0), -1.0, "too early to tell")
	assert_eq(RunProgress.left_words(31.0), "about 30 s left")
	assert_eq(RunProgress.left_words(400.0), "about 7 min left")
	assert_eq(
		RunProgress.line("Climbing the rail", 0.0045, 0.9),
		"Climbing the rail: 0.4 % done, estimating the time left."
	)
	assert_eq(RunProgress.line("Firing", 0.5, 20.0), "Firing: 50 % done, about 20 s left.")


func test_the_pachinko_bar_moves_during_the_rail_climbs() -> void:
	var panel := AnalysisPanel.new()
	add_child_autofree(panel)
	panel.bind(BoardLoader.load_board("res://levels/pachinko/classic.board").level)
	panel.start()
	var run: PachinkoAnalysis = panel._run
	# Wait (on the work, never on a clock) for the first climbs, before any shot is done.
	while run.phase == PachinkoAnalysis.Phase.CLIMBS and run.climb_progress() == 0.0:
		OS.delay_msec(20)
	var shots_done := run.progress()
	panel._process(0.016)
	var bar: float = panel._controls.progress.value
	var said: String = panel._controls.status.text
	panel.cancel()
	while panel.is_running():
		panel._process(0.016)
		OS.delay_msec(10)
	assert_eq(shots_done, 0.0, "no shot chunk was done yet")
	assert_gt(bar, 0.0, "yet the bar moved: the climbs are part of the run")
	assert_string_contains(said, "% done, ")


func test_a_maze_run_moves_before_its_first_game_ends() -> void:
	var level := BoardLoader.load_board("res://levels/maze/garden.board").level
	var run := MazeAnalysis.create(level, 1, 1)
	run.start(1)
	var share := 0.0
	var done := 0
	while share == 0.0 and not run.poll():
		done = run.games_done()
		share = run.progress()
		OS.delay_msec(20)
	run.cancel()
	run.wait()
	assert_eq(done, 0, "no game had finished")
	assert_gt(share, 0.0, "but the running game's share shows")
