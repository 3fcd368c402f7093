extends GutTest
## Losing a ball into a black hole (hard mode) reads at once: the ball drops into the hole
## with a sound, the panel's count says "3 of 4 balls left" with a flash, the note says
## the run can't be won any more at full strength (not fading in over two seconds), and once
## the ball is down a card offers Retry (focused) and Menu. A blind play trial saw none of it.

const GAME := preload("res://scenes/maze/maze_game.tscn")
const TEST_SETTINGS := "user://test_maze_hole_loss_settings.cfg"
const TEST_SAVE := "user://test_maze_hole_loss_save.cfg"


func before_all() -> void:
	App.load_player_files(TEST_SETTINGS, TEST_SAVE)
	App.request_board(BoardLevel.MAZE_NAME, "res://levels/maze/classic.board")


func after_all() -> void:
	App.load_player_files(App.SETTINGS_PATH, App.SAVE_PATH)
	for path in [TEST_SETTINGS, TEST_SAVE]:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(path))


# The game in hard mode with its first ball rolled into hole 1; returns the game.
func _lose_a_ball() -> MazeGame:
	var game: MazeGame = GAME.instantiate()
	add_child_autofree(game)
	var rules: MazeRules = game.rules
	rules.set_hard_mode(true)
	game._start()
	game._process(0.0)
	var id := rules.world.get_ids()[0]
	rules.world.set_ball_position(id, rules.level.holes[1] + Vector2(-12.0, 0.0))
	rules.world.set_ball_velocity(id, Vector2(60.0, 0.0))
	for i in 30:
		rules.step()
	return game


func test_the_panel_counts_the_lost_ball_with_a_flash() -> void:
	var game := _lose_a_ball()
	assert_eq(game.rules.state, MazeRules.State.LOST)
	assert_eq(game.rules.balls_left(), 3)
	assert_false(game.rules.can_still_win(), "a ball short: every ball must reach the dip")
	assert_eq(game.goal_count_text(), "3 of 4 balls left")
	assert_true(game.count_flashing(), "the count flashes")
	for i in 40:
		game._process(0.05)
	assert_false(game.count_flashing(), "a short flash")


func test_the_note_says_at_once_that_the_run_cannot_be_won() -> void:
	var game := _lose_a_ball()
	var note := game.get_node("%Note") as MazeNote
	assert_string_contains(note.text(), "can't be won")
	assert_eq(note.modulate.a, 1.0, "at full strength at once")


func test_once_the_ball_is_down_a_card_offers_retry() -> void:
	var game := _lose_a_ball()
	var card: MazeWinPanel = game.win_panel()
	assert_false(card.visible, "not over the falling ball")
	for i in 20:
		game._process(0.05)
	assert_true(card.visible, "the card is up once the ball has dropped")
	assert_string_contains(card.texts()[0], "Ball lost")
	assert_string_contains(" ".join(card.texts()), "can't be won")
	var buttons := card.buttons()
	assert_false(buttons[0].visible, "no Next board")
	assert_true(buttons[1].visible and buttons[2].visible, "Retry and Menu")
	await wait_process_frames(1)
	assert_true(buttons[1].has_focus(), "Retry has the focus")
	buttons[1].pressed.emit()
	assert_eq(game.rules.state, MazeRules.State.READY, "Retry puts the balls back")
	assert_false(card.visible)
	assert_eq(game.goal_count_text(), "In goal  0 / 4")


# A play trial on Cloister: two balls rolled into one hole together; the panel said "3 of 4
# left" while the card said "2 of 4 balls left" (the rules end the run at the first).
func test_two_balls_lost_at_once_read_the_same_on_the_panel_and_the_card() -> void:
	var game: MazeGame = GAME.instantiate()
	add_child_autofree(game)
	var rules: MazeRules = game.rules
	rules.set_hard_mode(true)
	game._start()
	game._process(0.0)
	var ids := rules.world.get_ids()
	for b in 2:
		var offset := Vector2(-12.0, 0.0) if b == 0 else Vector2(12.0, 0.0)
		rules.world.set_ball_position(ids[b], rules.level.holes[1] + offset)
		rules.world.set_ball_velocity(ids[b], -offset * 5.0)
	rules.advance(0.25)  # one slow frame: both fall within its steps
	assert_eq(rules.balls_left(), 2, "both balls fell")
	for i in 20:
		game._process(0.05)
	var card: MazeWinPanel = game.win_panel()
	assert_true(card.visible)
	assert_eq(game.goal_count_text(), "2 of 4 balls left", "the panel")
	assert_false("balls left" in " ".join(card.texts()), "the card says the loss plainly, no count")
