extends GutTest
## The clock keeps real time at low frame rates, so medals never depend on the computer's
## speed (a play trial on software GL: 20.5 s of real time read 0:14.4 at 4-17 FPS). Two
## things shortened it: the engine hands _process at most max_physics_steps_per_frame
## physics ticks of time (8 at 60/s: 0.133 s), and the world runs at most 30 steps (0.25 s)
## per advance.

const GAME := preload("res://scenes/maze/maze_game.tscn")
const TEST_SETTINGS := "user://test_maze_slow_frames_settings.cfg"
const TEST_SAVE := "user://test_maze_slow_frames_save.cfg"


func before_all() -> void:
	App.load_player_files(TEST_SETTINGS, TEST_SAVE)
	App.request_board(BoardLevel.MAZE_NAME, "res://levels/maze/garden.board")


func after_all() -> void:
	App.load_player_files(App.SETTINGS_PATH, App.SAVE_PATH)
	for path in [TEST_SETTINGS, TEST_SAVE]:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(path))


func test_the_engine_passes_slow_frames_on_whole() -> void:
	var ticks: int = ProjectSettings.get_setting("physics/common/physics_ticks_per_second")
	var most: int = ProjectSettings.get_setting("physics/common/max_physics_steps_per_frame")
	var longest := float(most) / float(ticks)
	assert_gte(longest, MazeFrameSteps.SLOWEST_FRAME, "frames up to 0.5 s reach _process whole")


func test_slow_frames_run_the_clock_at_real_time() -> void:
	var game: MazeGame = GAME.instantiate()
	add_child_autofree(game)
	game.rules.start()
	for seconds: float in [0.2, 0.4, 0.5]:
		var before := game.rules.elapsed
		game._process(seconds)
		assert_almost_eq(game.rules.elapsed - before, seconds, 0.01, "a %.1f s frame" % seconds)
	var before_hitch := game.rules.elapsed
	game._process(5.0)
	assert_almost_eq(
		game.rules.elapsed - before_hitch, MazeFrameSteps.SLOWEST_FRAME, 0.01, "a hitch is cut"
	)
