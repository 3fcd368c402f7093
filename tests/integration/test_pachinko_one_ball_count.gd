extends GutTest
## Trial 8 (issue 41): one ball count. The tray, the panel's "Balls" and "Won this game",
## the clear card's "You won", the restart prompt and the saved best all read the balls the
## player holds (a ball in flight is not held), and the best is a game's result (balls ended
## with less balls started), never its highest point.

const GAME := preload("res://scenes/pachinko/pachinko_game.tscn")
const BoardSwap := preload("res://tests/helpers/pachinko_board_swap.gd")

var _kept_save: RefCounted


func before_each() -> void:
	_kept_save = BoardSwap.begin()


func after_each() -> void:
	BoardSwap.end(_kept_save)


func _game() -> PachinkoGame:
	var game := GAME.instantiate() as PachinkoGame
	add_child_autofree(game)
	game.rules.start_game()
	return game


# The tray rises (or falls) by `balls`, as a payout does.
func _win(rules: PachinkoRules, balls: int) -> void:
	rules.cup += balls
	rules.cup_changed.emit(rules.cup)


# A ball caught by the board's first pocket, through the rules' own path: its payout pours.
func _pocket_hit(rules: PachinkoRules) -> int:
	var id := rules.place_ball(rules.level.pockets[0].position)
	rules.world.remove_ball(id)
	rules._on_ball_pocketed(id, 0)
	return maxi(rules.level.pockets[0].payout, 0)


func test_after_the_clearing_hit_every_count_agrees() -> void:
	# trial 8, bug 1: the card said "You won 11", the tray 36, the panel "Up 1"
	var game := _game()
	await wait_process_frames(1)
	var rules := game.rules
	var start := rules.level.cup_start_balls
	var target := PachinkoGoals.tray_target(rules.level)
	var payout := rules.level.pockets[0].payout
	assert_gt(payout, 1, "a pocket that pays more than one")
	_win(rules, target - rules.balls_to_shoot - 1)  # one short of the goal
	await wait_process_frames(2)
	_pocket_hit(rules)
	assert_true(game.cleared_card().visible, "the pocket's payout cleared the machine")
	var won := rules.balls_to_shoot - start
	assert_eq(game.cup.count(), rules.balls_to_shoot, "the tray holds the clearing payout")
	var shown := game.stats_panel.shown_text()
	assert_string_contains(shown, "Balls %d" % game.cup.count())
	assert_string_contains(shown, "Won this game +%d" % won)
	assert_string_contains(game.cleared_card().text(), "You won %d balls" % won)
	await wait_process_frames(5)
	assert_eq(game.cup.count(), rules.balls_to_shoot, "and still once the pour is over")
	assert_string_contains(game.stats_panel.shown_text(), "Won this game +%d" % won)


func test_a_game_that_peaked_and_came_back_keeps_its_result_not_its_peak() -> void:
	# trial 8, bugs 3 and 4: Windmills went +16, ended even, and kept 16
	var game := _game()
	var rules := game.rules
	var board := rules.level.board_id
	_win(rules, 16)
	_win(rules, -16)
	game.restart()  # leaves the game as Restart does
	assert_eq(App.best_pachinko_balls(board), -1, "an even game won nothing")
	game.rules.start_game()
	_win(game.rules, 16)
	_win(game.rules, -10)
	game.restart()
	assert_eq(App.best_pachinko_balls(board), 6, "the result, not the peak of 16")


func test_a_game_that_ran_dry_after_a_peak_records_nothing_won() -> void:
	var game := _game()
	var rules := game.rules
	var board := rules.level.board_id
	_win(rules, 16)
	rules.cup = 0
	rules.loaded = false
	rules.cup_changed.emit(0)
	rules._check_game_over()
	assert_eq(rules.state, PachinkoRules.State.GAME_OVER)
	assert_eq(App.best_pachinko_balls(board), 0, "played, nothing won")
	var body := game.instructions.get_node("Card/Margin/Box/Body") as RichTextLabel
	assert_false(body.get_parsed_text().contains("16"), body.get_parsed_text())


func test_new_best_only_when_a_result_beats_the_stored_one() -> void:
	var game := _game()
	var board := game.rules.level.board_id
	App.record_pachinko_balls(board, 10)
	_win(game.rules, 30)
	_win(game.rules, -25)
	game.restart()
	assert_eq(App.best_pachinko_balls(board), 10, "+5 does not beat +10, whatever its peak")


func test_the_restart_prompt_names_the_trays_count() -> void:
	# trial 8, bug 7: "Your 80 balls go" beside a tray of 79, one ball in flight
	var game := _game()
	var rules := game.rules
	_win(rules, 5)
	rules.fire(50.0)
	assert_eq(rules.balls_in_play(), 1, "a ball in flight")
	var key := InputEventAction.new()
	key.action = &"game_restart"
	key.pressed = true
	game._unhandled_input(key)
	assert_true(game.restart_prompt().asking())
	var words: String = game.restart_prompt()._line.get_parsed_text()
	assert_string_contains(words, "Your %d balls go" % game.cup.count())
	assert_eq(game.cup.count(), rules.balls_to_shoot)


func test_the_panel_follows_the_tray_in_the_same_frame() -> void:
	# trial 8, bug 2: the tray read 107 while the panel read "101 now"
	var game := _game()
	await wait_process_frames(1)
	game.cup.pour(6)
	_win(game.rules, 6)
	for frame in 20:
		await wait_process_frames(1)
		assert_string_contains(game.stats_panel.shown_text(), "Balls %d" % game.cup.count())


func test_the_panel_is_three_short_lines() -> void:
	var stats := {"shots": 243, "balls_left": 1234, "start_balls": 100, "pocket_hits": [97]}
	var lines := StatsPanel.lines_for(stats, 1200, 1350, false)
	assert_eq(lines.size(), 3)
	var text := "\n".join(lines)
	assert_string_contains(text, "[b]Balls[/b] 1234 · [b]goal[/b] 1350")
	assert_string_contains(text, "[b]Won this game[/b] +1134 · [b]best[/b] +1200")
	assert_string_contains(text, "[b]Pocket hits[/b] 97 of 243 shots")
	stats["balls_left"] = 93
	assert_string_contains("\n".join(StatsPanel.lines_for(stats)), "[b]Down[/b] 7 this game")
	assert_string_contains("\n".join(StatsPanel.lines_for(stats)), "best[/b] none yet")
