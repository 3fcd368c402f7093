extends GutTest
## Trial 9, complaint 3 and bugs 1 and 2: once a run ends the board eases back to level and
## the joystick's head back to the centre (a lost run's board stayed drawn at full tilt, "which
## looks like a freeze", and the head stayed off-centre behind the result card, won or lost,
## when a key had tilted the board), and a board opens in the mode the player last chose,
## through Next board or the list (easy, with a note, where it has no black holes; trial 10).

const GAME := preload("res://scenes/maze/maze_game.tscn")
const TEST_SETTINGS := "user://test_maze_run_over_settings.cfg"
const TEST_SAVE := "user://test_maze_run_over_save.cfg"
const CLASSIC := "res://levels/maze/classic.board"
const FRAME := 1.0 / 60.0


func before_all() -> void:
	App.load_player_files(TEST_SETTINGS, TEST_SAVE)


func after_all() -> void:
	Input.action_release(&"tilt_right")
	App.maze_hard_chosen = false
	App.request_board(BoardLevel.MAZE_NAME, CLASSIC)
	App.load_player_files(App.SETTINGS_PATH, App.SAVE_PATH)
	for path in [TEST_SETTINGS, TEST_SAVE]:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(path))


func before_each() -> void:
	App.maze_hard_chosen = false


func _game(path: String) -> MazeGame:
	App.request_board(BoardLevel.MAZE_NAME, path)
	var game: MazeGame = GAME.instantiate()
	add_child_autofree(game)
	return game


# Holds Right (as a player would, through the game's frames) with ball 0 sent at `target`
# from 12 px to its left, until the run ends; lets go. Returns the frames it took.
func _roll_in_with_right_held(game: MazeGame, target: Vector2) -> int:
	var rules := game.rules
	game._start()
	game._process(0.0)
	var id := rules.world.get_ids()[0]
	rules.world.set_ball_position(id, target + Vector2(-12.0, 0.0))
	rules.world.set_ball_velocity(id, Vector2(60.0, 0.0))
	Input.action_press(&"tilt_right")
	var frames := 0
	while rules.is_playing() and frames < 120:
		game._process(FRAME)
		frames += 1
	Input.action_release(&"tilt_right")
	return frames


func _joystick(game: MazeGame) -> MazeJoystick:
	return game.get_node("%Joystick") as MazeJoystick


func test_a_lost_run_levels_the_board_and_centres_the_joystick() -> void:
	var game := _game(CLASSIC)
	game.rules.set_hard_mode(true)
	_roll_in_with_right_held(game, game.rules.level.holes[1])
	assert_eq(game.rules.state, MazeRules.State.LOST, "the ball fell into the hole")
	assert_ne(game.rules.tilt, Vector2.ZERO, "the key still tilted the board as it fell")
	var at_loss := game.rules.ball_positions()
	for i in 12:  # 0.2 s
		game._process(FRAME)
	assert_eq(game.rules.tilt, Vector2.ZERO, "the board has eased back to level")
	assert_eq(_joystick(game).head_offset, Vector2.ZERO, "the head is back in the centre")
	var after := game.rules.ball_positions()
	for b in range(1, at_loss.size()):
		assert_eq(after[b], at_loss[b], "ball %d stays where it was" % b)


func test_a_won_run_centres_the_joystick_behind_the_card() -> void:
	var game := _game("res://levels/maze/first_roll.board")
	_roll_in_with_right_held(game, game.rules.level.goal_center)
	assert_eq(game.rules.state, MazeRules.State.WON)
	for i in 12:
		game._process(FRAME)
	assert_eq(_joystick(game).head_offset, Vector2.ZERO, "no key held: the head is centred")


func test_next_board_from_a_hard_run_opens_in_hard_mode() -> void:
	App.maze_hard_chosen = true
	var game := _game("res://levels/maze/cloister.board")
	assert_true(game.rules.hard_mode, "Cloister has black holes: hard mode")
	# trial 10: a board picked through "Other boards" after a hard run opened in easy mode
	var again := _game("res://levels/maze/switchbacks.board")
	assert_true(again.rules.hard_mode, "the board picked from the list opens in hard mode too")


func test_the_mode_chosen_with_h_and_e_holds_for_the_boards_opened_next() -> void:
	var game := _game("res://levels/maze/cloister.board")
	assert_false(game.rules.hard_mode, "easy until the player asks")
	game._unhandled_input(_action(&"maze_hard_mode"))
	assert_true(game.rules.hard_mode)
	assert_true(_game("res://levels/maze/switchbacks.board").rules.hard_mode, "hard kept")
	var easy := _game("res://levels/maze/long_hall.board")
	easy._unhandled_input(_action(&"maze_easy_mode"))
	assert_false(easy.rules.hard_mode)
	assert_false(_game("res://levels/maze/labyrinth.board").rules.hard_mode, "easy kept")


func _action(action: StringName) -> InputEventAction:
	var event := InputEventAction.new()
	event.action = action
	event.pressed = true
	return event


func test_next_board_from_a_hard_run_without_holes_opens_easy_with_a_note() -> void:
	App.maze_hard_chosen = true
	var game := _game("res://levels/maze/two_together.board")
	assert_false(game.rules.hard_mode)
	var note := game.get_node("%Note") as MazeNote
	assert_string_contains(note.text(), "No black holes")
