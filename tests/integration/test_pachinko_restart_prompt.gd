extends GutTest
## R never throws a cup away silently (a play trial lost 80 balls to one R): a session with
## balls won or more than one shot in asks first, a second R starts over, Esc keeps playing.
## The handle's strength is kept across games and boards, in the player's save file.

const GAME := preload("res://scenes/pachinko/pachinko_game.tscn")
const BoardSwap := preload("res://tests/helpers/pachinko_board_swap.gd")
const SAVE_PATH := "user://test_restart_prompt_save.cfg"

var _kept_save: RefCounted


func before_each() -> void:
	_kept_save = BoardSwap.begin()


func after_each() -> void:
	BoardSwap.end(_kept_save)
	DirAccess.remove_absolute(ProjectSettings.globalize_path(SAVE_PATH))


func _playing_game() -> PachinkoGame:
	var game := GAME.instantiate() as PachinkoGame
	add_child_autofree(game)
	game.rules.start_game()
	return game


func _action(action: StringName) -> InputEventAction:
	var event := InputEventAction.new()
	event.action = action
	event.pressed = true
	return event


func _stream(rules: PachinkoRules, seconds: float) -> void:
	rules.handle.grip()
	for i in int(seconds / rules.step_seconds()):
		rules.step()
	rules.handle.let_go()


func test_r_on_a_fresh_game_starts_over_at_once() -> void:
	var game := _playing_game()
	await wait_process_frames(1)
	var first := game.rules
	game._unhandled_input(_action(&"game_restart"))
	assert_ne(game.rules, first, "nothing to lose: a new game")
	assert_false(game.restart_prompt().asking())


func test_r_asks_first_when_the_cup_has_shots_in_and_a_second_r_starts_over() -> void:
	var game := _playing_game()
	await wait_process_frames(1)
	var first := game.rules
	_stream(first, 4.0)
	assert_gt(first.stats(true).get("game_shots", 0), 1, "shots in")
	game._unhandled_input(_action(&"game_restart"))
	assert_eq(game.rules, first, "the game goes on")
	assert_true(game.restart_prompt().asking(), "R asks first")
	# trial 8: the count is the tray's, the balls held; a ball in the air is not held
	var in_play: int = first.stats(true).get("in_play", 0)
	assert_gt(in_play, 0, "balls still in play")
	assert_eq(game.cup.count(), first.balls_to_shoot, "the tray settled for the question")
	var count := first.balls_to_shoot
	assert_string_contains(game.restart_prompt().text(), "Your %d balls go" % count)
	game._unhandled_input(_action(&"game_restart"))
	assert_ne(game.rules, first, "a second R starts over")
	assert_false(game.restart_prompt().asking())


func test_a_second_r_a_few_seconds_later_still_starts_over() -> void:
	# Trial 6: R, then R again "about 2 s later" (16 FPS, screenshots between): the question
	# had gone at 4 s, so the second R asked again and nothing reset
	var game := _playing_game()
	await wait_process_frames(1)
	var first := game.rules
	_stream(first, 4.0)
	game._unhandled_input(_action(&"game_restart"))
	assert_true(game.restart_prompt().asking())
	await wait_seconds(5.5)
	assert_true(game.restart_prompt().asking(), "still asking after 5.5 s")
	game._unhandled_input(_action(&"game_restart"))
	assert_ne(game.rules, first, "the second R starts over")


func test_esc_answers_keep_playing() -> void:
	var game := _playing_game()
	await wait_process_frames(1)
	var first := game.rules
	_stream(first, 4.0)
	game._unhandled_input(_action(&"game_restart"))
	game.restart_prompt()._unhandled_input(_action(&"pause"))
	assert_false(game.restart_prompt().asking(), "the question goes")
	assert_false(game.pause_menu.is_open(), "without opening the pause menu")
	assert_eq(game.rules, first, "the game goes on")


func test_the_handle_strength_is_kept_across_games_boards_and_runs() -> void:
	var game := _playing_game()
	await wait_process_frames(1)
	game.rules.handle.set_power(82.0)
	game.restart()
	assert_eq(game.rules.handle.power, 82.0, "the next game starts with it")
	App.request_board("pachinko", "res://levels/pachinko/classic.board")
	var other := _playing_game()
	await wait_process_frames(1)
	assert_eq(other.rules.handle.power, 82.0, "and the next board")
	var saved := SaveData.new()
	assert_eq(saved.load_file(SAVE_PATH), "")
	saved.keep_pachinko_handle_power(37.0)
	var again := SaveData.new()
	assert_eq(again.load_file(SAVE_PATH), "")
	assert_eq(again.pachinko_handle_power(), 37.0, "saved with the player's file")
	assert_eq(SaveData.new().pachinko_handle_power(), -1.0, "none before it is turned")
