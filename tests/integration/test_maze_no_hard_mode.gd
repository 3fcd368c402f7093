extends GutTest
## A board without black holes has no hard mode (trial 8: H on First Roll said "hard mode is
## the same as easy", yet the best time went to "--" and a hard record of its own began).

const GAME := preload("res://scenes/maze/maze_game.tscn")
const TEST_SETTINGS := "user://test_maze_no_hard_settings.cfg"
const TEST_SAVE := "user://test_maze_no_hard_save.cfg"


func before_all() -> void:
	App.load_player_files(TEST_SETTINGS, TEST_SAVE)


func after_all() -> void:
	App.maze_hard_chosen = false  # H here is the player's choice for the next board
	App.request_board(BoardLevel.MAZE_NAME, "res://levels/maze/classic.board")
	App.load_player_files(App.SETTINGS_PATH, App.SAVE_PATH)
	for path in [TEST_SETTINGS, TEST_SAVE]:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(path))


func _game(board: String) -> MazeGame:
	App.request_board(BoardLevel.MAZE_NAME, "res://levels/maze/%s.board" % board)
	var game: MazeGame = GAME.instantiate()
	add_child_autofree(game)
	return game


func _press_hard(game: MazeGame) -> void:
	var event := InputEventAction.new()
	event.action = &"maze_hard_mode"
	event.pressed = true
	game._unhandled_input(event)


func test_h_on_a_board_without_holes_keeps_easy_mode_and_says_why() -> void:
	var game := _game("first_roll")
	_press_hard(game)
	assert_false(game.rules.hard_mode, "First Roll stays in easy mode")
	var note := str(game.get_node("%Note").text())
	assert_string_contains(note, "no hard mode", "the note says why")


func test_h_on_a_board_with_holes_still_switches() -> void:
	var game := _game("cloister")
	_press_hard(game)
	assert_true(game.rules.hard_mode, "Cloister goes to hard mode")
