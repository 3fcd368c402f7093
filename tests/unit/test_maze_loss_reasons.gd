extends GutTest
## The maze analysis explains its lost games: a hopeless game is given up within seconds of
## play (a ball trapped behind a gap narrower than a ball, or no progress for 20 s), each
## game says why and where it was lost, the losses are grouped and worded for the dock.

const MazeLossWords := preload("res://addons/board_editor/analysis/maze_loss_words.gd")
const MazeAnalysisPanel := preload("res://addons/board_editor/analysis/maze_analysis_panel.gd")
const TEST_FOLDER := "user://test_maze_loss_reasons"

var _saved_folder := ""


func before_each() -> void:
	_saved_folder = AnalysisCache.folder_override
	AnalysisCache.folder_override = TEST_FOLDER


func after_each() -> void:
	if DirAccess.dir_exists_absolute(TEST_FOLDER):
		for file in DirAccess.get_files_at(TEST_FOLDER):
			DirAccess.remove_absolute(TEST_FOLDER.path_join(file))
	AnalysisCache.folder_override = _saved_folder


# The classic maze's frame and starts, no holes, and one wall across it at x = 100 whose top
# end cap stops 5 px below the top wall's face: the two left balls can never reach the goal.
func _trap_board() -> BoardLevel:
	var level: BoardLevel = BoardLoader.load_board("res://levels/maze/classic.board").level
	var frame := [Vector2(0, 0), Vector2(350, 0), Vector2(0, 0), Vector2(0, 315)]
	frame.append_array([Vector2(0, 315), Vector2(350, 315), Vector2(350, 0), Vector2(350, 315)])
	frame.append_array([Vector2(100, 15), Vector2(100, 315)])
	level.walls = PackedVector2Array(frame)
	level.wall_ids = PackedInt32Array()
	level.holes = PackedVector2Array()
	level.hole_ids = PackedInt32Array()
	ItemIds.fill(level)
	return level


func test_a_five_pixel_trap_is_given_up_at_once_and_named_at_the_gap() -> void:
	var level := _trap_board()
	var report := MazeAnalysis.run(level, 2, 1, 2)
	var games: Array = report["games"]
	assert_eq(games.size(), 4, "two games a mode")
	for game: Dictionary in games:
		assert_eq(game["reason"], "trapped", str(game))
		assert_lt(float(game["seconds"]), 3.0, "given up within seconds of play, not 120 s")
		assert_eq(int(game["ball"]), 0, "the first start's ball, shut in on the left")
		var ends: Array = game["ends"]
		assert_eq(ends.size(), 4, "where every ball ended")
	var losses: Array = report["losses"]
	assert_eq(losses.size(), 1, "one place, one reason: %s" % str(losses))
	var entry: Dictionary = losses[0]
	assert_eq(int(entry["games"]), 4)
	var at: Array = entry["at"]
	assert_lt(float(at[0]), 95.0, "where it ended: left of the wall, shut in: %s" % str(at))
	var gap: Array = entry["gap"]
	assert_eq(gap.size(), 2, "the gap that shuts it in is named")
	if gap.size() == 2:
		assert_lt(Vector2(gap[0], gap[1]).distance_to(Vector2(100, 7.5)), 3.0, str(gap))
	var words := MazeLossWords.lines(report)
	assert_eq(words.size(), 1)
	var expected := (
		"4 of 4 games: a ball was trapped near %s, with no way out wide enough for it "
		+ "(the gap at (100, 8) is narrower than a ball)."
	)
	assert_eq(words[0], expected % MazeLossWords.place(at))


func test_the_dock_names_a_trap_the_board_check_proves_at_once() -> void:
	# The board check already proves the trap (the gap is narrower than a ball), so the dock
	# says so without playing a game; the games' own loss words are checked above.
	var panel := MazeAnalysisPanel.new()
	panel.runs = 1
	add_child_autofree(panel)
	panel.bind(_trap_board())
	panel.start()
	assert_false(panel.is_running(), "no games played")
	var status: String = panel._controls.status.text
	assert_string_contains(status, "this board cannot be won")
	assert_string_contains(status, "Ball starts 1 and 3 cannot roll to the goal: walls ")


func test_no_progress_for_twenty_seconds_is_stuck() -> void:
	var level := _trap_board()
	level.walls = PackedVector2Array(Array(level.walls).slice(0, 8))  # the frame alone
	ItemIds.fill(level)
	var watch := MazeProgressWatch.new(MazeNav.new(level), MazeFlood.new(level, false), 2)
	var dt := 0.05
	var near := level.goal_center + Vector2(40, 0)
	var far := Vector2(20, 20)
	var positions := PackedVector2Array([near, far])
	var seconds := 0.0
	while seconds < 19.0:
		assert_eq(watch.look(positions, 0, dt), MazeProgressWatch.Verdict.PLAYING)
		seconds += dt
	# The far ball comes 30 px nearer: progress, so the wait starts again.
	positions[1] = far + Vector2(30, 0)
	watch.look(positions, 0, 0.3)
	assert_lt(watch.idle_seconds, 0.5, "progress resets the patience")
	var verdict := MazeProgressWatch.Verdict.PLAYING
	seconds = 0.0
	while verdict == MazeProgressWatch.Verdict.PLAYING and seconds < 30.0:
		verdict = watch.look(positions, 0, dt)
		seconds += dt
	assert_eq(verdict, MazeProgressWatch.Verdict.STUCK)
	assert_almost_eq(seconds, MazeProgressWatch.PATIENCE, 0.5, "after the patience, not later")
	assert_eq(watch.culprit, 1, "the ball that stayed furthest from the goal")
	assert_eq(watch.verdict_name(), "stuck")


func test_losses_group_by_reason_and_place_and_read_as_a_designer_would() -> void:
	var level := _trap_board()
	var flood := MazeFlood.new(level, false)
	var games: Array[Dictionary] = [
		{"reason": "stuck", "hard": false, "at": [120.0, 340.0], "idle_s": 20.2, "seconds": 50.0},
		{"reason": "stuck", "hard": true, "at": [124.0, 336.0], "idle_s": 20.2, "seconds": 31.0},
		{"reason": "stuck", "hard": true, "at": [116.0, 344.0], "idle_s": 19.6, "seconds": 40.0},
		{"reason": "won", "hard": false, "at": [], "seconds": 40.0},
		{"reason": "timeout", "hard": false, "at": [300.0, 40.0], "seconds": 120.0},
	]
	var losses := MazeLosses.group(level, games, flood, [])
	assert_eq(losses.size(), 2, str(losses))
	var stuck: Dictionary = losses[0]
	assert_eq(stuck["reason"], "stuck", "the most games first")
	assert_eq(int(stuck["games"]), 3)
	assert_eq(stuck["at"], [120.0, 340.0], "the mean place")
	var words := MazeLossWords.line(stuck, 12)
	assert_eq(words, "3 of 12 games: a ball was stuck near (120, 340) for 20 s.")
	assert_eq(
		MazeLossWords.line(losses[1], 12),
		"1 of 12 games: time ran out (120 s) with a ball still near (300, 40) (easy mode)."
	)
	var hole := {"reason": "hole", "games": 2, "hard": 2, "hole": 7, "at": [87.5, 17.5]}
	assert_eq(MazeLossWords.line(hole, 12), "2 of 12 games: a ball fell into hole 7 at (88, 18).")
	assert_eq(MazeLossWords.tag(stuck), "stuck ×3")
