extends GutTest
## A pachinko session left before its cup ran dry still counts for the board's best session
## (a play trial left Hanami at 277 balls through the pause menu and its card said "Not
## played yet"); a session that paid nothing back records nothing.

const GAME := "res://scenes/pachinko/pachinko_game.tscn"
const TEST_SETTINGS := "user://test_session_kept_settings.cfg"
const TEST_SAVE := "user://test_session_kept_save.cfg"


func before_each() -> void:
	for path in [TEST_SETTINGS, TEST_SAVE]:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(path))
	App.load_player_files(TEST_SETTINGS, TEST_SAVE)


func after_all() -> void:
	App.load_player_files(App.SETTINGS_PATH, App.SAVE_PATH)
	for path in [TEST_SETTINGS, TEST_SAVE]:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(path))


func _playing_game() -> PachinkoGame:
	var game := (load(GAME) as PackedScene).instantiate() as PachinkoGame
	add_child(game)
	game.rules.start_game()
	return game


func test_leaving_a_session_that_paid_keeps_it_as_the_best() -> void:
	var game := _playing_game()
	var board := game.rules.level.board_id
	# under the board's goal: a clear keeps its result at once (trial 9)
	_win(game.rules, 5)
	assert_eq(App.best_pachinko_balls(board), -1, "nothing recorded while playing")
	game.free()
	assert_eq(App.best_pachinko_balls(board), 5, "the session is kept on leaving")


func test_restarting_keeps_the_session_too() -> void:
	var game := _playing_game()
	var board := game.rules.level.board_id
	_win(game.rules, 25)
	game.restart()
	assert_eq(App.best_pachinko_balls(board), 25)
	game.free()


func test_a_session_that_paid_nothing_records_nothing() -> void:
	var game := _playing_game()
	var board := game.rules.level.board_id
	game.free()
	assert_eq(App.best_pachinko_balls(board), -1)


# A play trial found R dropped the session while the pause menu's Restart and Other boards
# kept it: the key now ends the game the same way (after asking, a later trial lost its cup).
func test_the_restart_key_keeps_the_session_like_the_menu() -> void:
	var game := _playing_game()
	var board := game.rules.level.board_id
	_win(game.rules, 5)  # under the board's goal: R does nothing over the win card
	var key := InputEventAction.new()
	key.action = &"game_restart"
	key.pressed = true
	game._unhandled_input(key)
	assert_true(game.restart_prompt().asking(), "a session that paid asks first")
	game._unhandled_input(key)
	assert_eq(App.best_pachinko_balls(board), 5, "R keeps the session as Restart does")
	assert_ne(game.rules.state, PachinkoRules.State.PLAYING, "and starts a new game")
	assert_string_contains(game.notes.text, "new game", "the key reads as a new game")
	assert_string_contains(
		game.instructions._body.text, "still counts for your best", "the card says so"
	)
	game.free()


# The cup showed one ball fewer than the board gives (one sits in the launcher): it counts
# every ball the player still has to shoot.
func test_the_cup_shows_every_ball_to_shoot() -> void:
	var game := _playing_game()
	var start := game.rules.level.cup_start_balls
	assert_eq(game.rules.balls_to_shoot, start, "cup and launcher together")
	assert_eq(game.cup.count(), start, "the cup shows the board's start balls, not one fewer")
	game.rules.fire(50.0)
	assert_eq(game.cup.count(), start - 1, "one fewer once a ball is shot")
	game.free()


# The tray rises by `balls` (as a payout does): the game has won them.
func _win(rules: PachinkoRules, balls: int) -> void:
	rules.cup += balls
	rules.cup_changed.emit(rules.cup)


# A play trial: "Best: N balls paid back" rewarded a long session over a good one (a 100-ball
# board out-scored a 25-ball one by lasting). The best is the game's result: the balls it
# ended with above its start (trial 8: not its highest point), however much was paid back.
func test_the_best_is_the_result_not_the_balls_paid_back() -> void:
	var game := _playing_game()
	var board := game.rules.level.board_id
	game.rules.ledger.paid += 300  # paid back, all shot away again
	_win(game.rules, 6)  # under the board's goal: a clear's result counts at once (trial 9)
	_win(game.rules, -3)
	game.free()
	assert_eq(App.best_pachinko_balls(board), 3, "the tray ended 3 above its start")
