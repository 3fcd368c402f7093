extends GutTest
## The clock keeps real time at low frame rates, so medals never depend on the computer's
## speed (a play trial on software GL: 20.5 s of real time read 0:14.4 at 4-17 FPS). Two
## things shortened it: the engine hands _process at most max_physics_steps_per_frame
## physics ticks of time (8 at 60/s: 0.133 s), and the world runs at most 30 steps (0.25 s)
## per advance. A later trial at 2-6 FPS still saw it slow: frames over 0.5 s were cut; now
## frames up to 2 s count whole, and the keys ease the tilt piece by piece as they would
## frame by frame.

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
	assert_gte(longest, MazeFrameSteps.SLOWEST_FRAME, "frames up to 2 s reach _process whole")


func test_slow_frames_run_the_clock_at_real_time() -> void:
	var game: MazeGame = GAME.instantiate()
	add_child_autofree(game)
	game.rules.start()
	for seconds: float in [0.2, 0.4, 0.5, 1.0, 2.0]:
		var before := game.rules.elapsed
		game._process(seconds)
		assert_almost_eq(game.rules.elapsed - before, seconds, 0.01, "a %.1f s frame" % seconds)
	var before_hitch := game.rules.elapsed
	game._process(5.0)
	assert_almost_eq(
		game.rules.elapsed - before_hitch, MazeFrameSteps.SLOWEST_FRAME, 0.01, "a hitch is cut"
	)


# Holds the right-hand key for one second of frames `frame` s long from a fresh start and
# returns where the first ball got to and the tilt it ended with.
func _hold_right_for_a_second(frame: float) -> Array:
	var game: MazeGame = GAME.instantiate()
	add_child_autofree(game)
	game.rules.start()
	Input.action_press("tilt_right")
	for i in roundi(1.0 / frame):
		game._process(frame)
	Input.action_release("tilt_right")
	var id := game.rules.world.get_ids()[0]
	var moved := game.rules.world.get_ball_position(id) - game.rules.level.ball_starts[0]
	return [moved, game.rules.tilt, game.rules.elapsed]


# At 1 frame a second the board answers a held key as it does at 60: the same clock, the
# same full tilt, the ball as far along (the whole frame once ran at the tilt its end had
# reached, and frames over 0.5 s were cut).
func test_a_held_key_tilts_alike_at_one_frame_a_second() -> void:
	var smooth := _hold_right_for_a_second(1.0 / 60.0)
	var slow := _hold_right_for_a_second(1.0)
	assert_almost_eq(slow[2], smooth[2], 0.02, "a second on the clock either way")
	assert_almost_eq(slow[1].x, smooth[1].x, 0.01, "the same tilt after a second")
	assert_almost_eq(slow[0].x, smooth[0].x, 4.0, "the ball as far along: %s" % [[smooth, slow]])
