extends GutTest
## At the finish the balls settle inside the goal's dip and the board eases back to level (a
## play trial saw the board freeze tilted with the last ball drawn on the dip's rim, half
## outside the ring).

const GAME := preload("res://scenes/maze/maze_game.tscn")
const TEST_SETTINGS := "user://test_maze_finish_settles_settings.cfg"
const TEST_SAVE := "user://test_maze_finish_settles_save.cfg"


func before_all() -> void:
	App.load_player_files(TEST_SETTINGS, TEST_SAVE)
	App.request_board(BoardLevel.MAZE_NAME, "res://levels/maze/first_roll.board")


func after_all() -> void:
	# the next test files expect the default board, as the other maze tests leave it
	App.request_board(BoardLevel.MAZE_NAME, "res://levels/maze/classic.board")
	App.load_player_files(App.SETTINGS_PATH, App.SAVE_PATH)
	for path in [TEST_SETTINGS, TEST_SAVE]:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(path))


func test_the_ball_settles_in_the_dip_and_the_board_levels() -> void:
	var game: MazeGame = GAME.instantiate()
	add_child_autofree(game)
	var rules: MazeRules = game.rules
	var level := rules.level
	game._start()
	var id := rules.world.get_ids()[0]
	# on the rim, rolling out, the board tilted away from the middle
	var rim := level.goal_center + Vector2(-(level.goal_radius - 1.0), 0.0)
	rules.world.set_ball_position(id, rim)
	rules.world.set_ball_velocity(id, Vector2(-40.0, 0.0))
	rules.set_tilt(Vector2(-TiltInput.MAX_TILT_DEG, 0.0))
	rules.step()
	assert_eq(rules.state, MazeRules.State.WON)
	var clock := rules.elapsed
	for i in 90:
		game._process(1.0 / 60.0)
	var from_middle := rules.world.get_ball_position(id).distance_to(level.goal_center)
	assert_lt(
		from_middle + level.ball_radius,
		level.goal_radius,
		"the ball lies wholly inside the ring (%.1f px from the middle)" % from_middle
	)
	assert_eq(game.stage().shown_tilt(), Vector2.ZERO, "the board is level again")
	assert_eq(rules.elapsed, clock, "the clock stays stopped")
	assert_eq(rules.state, MazeRules.State.WON)
