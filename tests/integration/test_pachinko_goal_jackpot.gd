extends GutTest
## Trial 6: MACHINE CLEARED! came up mid-jackpot and froze it (the attacker open, balls in
## the air, until a click). Reached mid-jackpot, the goal waits until the jackpot is over
## and its last balls have landed (JackpotSettle), then the card comes up.

const GAME := preload("res://scenes/pachinko/pachinko_game.tscn")
const BoardSwap := preload("res://tests/helpers/pachinko_board_swap.gd")

var _kept_save: RefCounted


func before_each() -> void:
	_kept_save = BoardSwap.begin()


func after_each() -> void:
	BoardSwap.end(_kept_save)


func test_the_goal_reached_mid_jackpot_waits_for_its_end_and_last_ball() -> void:
	var game := GAME.instantiate() as PachinkoGame
	add_child_autofree(game)
	await wait_process_frames(1)
	var rules := game.rules
	rules.start_game()
	var ball := rules.fire(70.0)
	assert_gte(ball, 0)
	var rounds := rules.bonus.rounds
	rounds.begin()
	assert_true(rounds.active(), "a jackpot is on")
	rules.cup += PachinkoGoals.tray_target(rules.level)
	rules.cup_changed.emit(rules.cup)
	assert_false(game.cleared_card().visible, "reached mid-jackpot: no card yet")
	rounds.current_round = JackpotRounds.ROUNDS
	rounds.end_round()
	assert_false(rounds.active(), "its last round is over")
	assert_false(game.cleared_card().visible, "a ball of its last round is still falling")
	rules.ball_drained.emit(ball)
	await wait_process_frames(1)
	assert_true(game.cleared_card().visible, "the jackpot is over: the card comes up")
	assert_false(game.bonus_view().banner.is_showing(), "no JACKPOT OVER card under it")
	assert_string_contains(game.cleared_card().text(), "CLEARED")
	# trial 9: no "what it paid" was seen; the clear's card takes the summary's place
	assert_string_contains(game.cleared_card().text(), "The jackpot paid")


func test_the_jackpot_over_card_counts_its_last_balls() -> void:
	# Trial 6: "533 balls paid" on the card while the panel said 550
	var game := GAME.instantiate() as PachinkoGame
	add_child_autofree(game)
	await wait_process_frames(1)
	var rules := game.rules
	rules.start_game()
	var ball := rules.fire(70.0)
	var rounds := rules.bonus.rounds
	rounds.begin()
	rounds.current_round = JackpotRounds.ROUNDS
	rounds.end_round()
	var banner := game.bonus_view().banner
	assert_false(banner.caption().contains("JACKPOT OVER"), "its last ball is still falling")
	rules.ledger.record_win(0, 17)  # the last ball lands in a pocket paying 17
	rules.ball_won.emit(ball, 0, 17, Vector2.ZERO)
	var paid: int = rules.stats(true)["payouts"]
	assert_string_contains(banner.caption(), "JACKPOT OVER")
	assert_string_contains(banner.caption(), "%d balls" % paid, "the panel's count")
