extends GutTest
## The editor's maze play analysis driven headless: the pilot's games run in the background
## and their figures show in the dock and stay for the same board content; an edit makes
## them stale; cancel stops the games and keeps nothing; the holes that swallowed balls are
## named by their stable ids.

const MazeAnalysisPanel := preload("res://addons/board_editor/analysis/maze_analysis_panel.gd")
const MazeAnalysisDraw := preload("res://addons/board_editor/analysis/maze_analysis_draw.gd")
const GARDEN := "res://levels/maze/garden.board"
## The panel keeps its figures on disk: the tests keep theirs apart.
const TEST_FOLDER := "user://test_maze_analysis_editor"

var _saved_folder := ""


func before_each() -> void:
	_saved_folder = AnalysisCache.folder_override
	AnalysisCache.folder_override = TEST_FOLDER


func after_each() -> void:
	if DirAccess.dir_exists_absolute(TEST_FOLDER):
		for file in DirAccess.get_files_at(TEST_FOLDER):
			DirAccess.remove_absolute(TEST_FOLDER.path_join(file))
	AnalysisCache.folder_override = _saved_folder


func _panel() -> MazeAnalysisPanel:
	var panel := MazeAnalysisPanel.new()
	panel.runs = 1
	add_child_autofree(panel)
	return panel


func _garden() -> BoardLevel:
	return BoardLoader.load_board(GARDEN).level


# Lets the panel poll its run the way the editor's frames would.
func _finish(panel: MazeAnalysisPanel) -> void:
	var started := Time.get_ticks_msec()
	while panel.is_running() and Time.get_ticks_msec() - started < 120000:
		panel._process(0.016)
		OS.delay_msec(10)


func test_the_pilots_games_show_and_stay_for_the_same_board() -> void:
	var level := _garden()
	var panel := _panel()
	panel.bind(level)
	assert_true(panel.visible, "a maze board shows the section")
	assert_true(panel.report().is_empty(), "nothing analysed yet")
	panel.start()
	assert_true(panel.is_running(), "the games run in the background")
	_finish(panel)
	assert_false(panel.is_running())
	var report := panel.report()
	assert_eq(report.get("game"), "maze")
	for mode: String in ["easy", "hard"]:
		var figures: Dictionary = report[mode]
		assert_eq(figures["games"], 1, "%s: one game played" % mode)
	assert_string_contains(panel._controls.status.text, "Easy: won ")
	assert_string_contains(panel._controls.status.text, "2 games in ")
	# An edit makes the figures stale; undoing back to the same content brings them back.
	var start := level.ball_starts[0]
	level.ball_starts[0] = start + Vector2(0, 5)
	panel.bind(level)
	assert_true(panel.report().is_empty(), "an edited board has no figures")
	assert_string_contains(panel._controls.status.text, "Not analysed")
	level.ball_starts[0] = start
	panel.bind(level)
	assert_eq(panel.report(), report, "the same content shows its figures again")
	# A rename and "Save board as" (a new name and board id) keep the figures.
	level.display_name = "Garden Path, renamed"
	level.board_id = "maze_garden_copy"
	panel.bind(level)
	assert_eq(panel.report(), report, "a renamed board keeps its analysis")
	# The next editor session (a fresh panel) finds them on disk.
	var later := _panel()
	later.bind(_garden())
	assert_eq(later.report().get("game"), "maze", "kept on disk like pachinko's")
	var easy: Dictionary = later.report()["easy"]
	assert_eq(int(easy["games"]), 1)
	assert_string_contains(later._controls.status.text, "Easy: won ")


func test_cancel_stops_the_games_and_keeps_nothing() -> void:
	var panel := _panel()
	panel.runs = 8
	panel.bind(_garden())
	panel.start()
	panel.cancel()
	var started := Time.get_ticks_msec()
	_finish(panel)
	assert_lt(Time.get_ticks_msec() - started, 20000, "cancelled games stop at their next frame")
	assert_false(panel.is_running())
	assert_true(panel.report().is_empty())
	assert_string_contains(panel._controls.status.text, "Cancelled")


func test_a_pachinko_board_hides_the_section() -> void:
	var panel := _panel()
	panel.bind(BoardLoader.load_board("res://levels/pachinko/classic.board").level)
	assert_false(panel.visible)
	panel.start()
	assert_false(panel.is_running())


func test_a_cancelled_analysis_counts_only_finished_games() -> void:
	var analysis := MazeAnalysis.create(_garden(), 4, 1)
	analysis.start(2)
	analysis.cancel()
	while not analysis.poll():
		OS.delay_msec(5)
	var report := analysis.report()
	var easy: Dictionary = report["easy"]
	var hard: Dictionary = report["hard"]
	assert_eq(int(easy["games"]) + int(hard["games"]), analysis.games_done(), "only finished games")
	assert_lt(analysis.games_done(), 8, "cancel stopped games that were under way")


func test_holes_are_named_by_their_stable_ids_in_words() -> void:
	var holes: Array = [{"id": 7, "index": 0, "balls": 2}, {"id": 12, "index": 3, "balls": 1}]
	assert_eq(
		MazeAnalysisDraw.holes_line(holes), "Balls lost in hard mode: hole 7 (2), hole 12 (1)"
	)
	var figures := {"games": 6, "wins": 5, "median_time_s": 41.23}
	assert_eq(MazeAnalysisDraw.mode_line("hard", figures), "Hard: won 5 of 6, median 41.2 s")
	assert_eq(MazeAnalysisDraw.mode_line("easy", {"games": 3, "wins": 0}), "Easy: won 0 of 3")


func test_a_board_the_check_proves_unwinnable_plays_no_games() -> void:
	var level := _garden()
	var walls := level.walls
	var c := level.goal_center
	var half := level.goal_radius + level.wall_width + level.ball_radius + 2.0
	var corners := [c + Vector2(-half, -half), c + Vector2(half, -half)]
	corners.append_array([c + Vector2(half, half), c + Vector2(-half, half)])
	for k in 4:
		walls.append(corners[k])
		walls.append(corners[(k + 1) % 4])
	level.walls = walls
	ItemIds.fill(level)
	var panel := _panel()
	panel.bind(level)
	panel.start()
	assert_false(panel.is_running(), "no pilot games on a board nobody can win")
	var said := panel._controls.status.text
	assert_string_contains(said, "No games played: this board cannot be won.")
	assert_string_contains(said, "The goal is closed in by walls ")
