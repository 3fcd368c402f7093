extends GutTest
## Trial 8, bug 5: a jackpot came straight after another ended, and "JACKPOT OVER" covered
## it while its round 1 clock ran ("9 s · 10 left", then "2 s" with nothing caught). A
## jackpot back to back with the last is announced ("JACKPOT AGAIN!") and its round 1 opens,
## its clock with it, only once the announcement is over.

const GAME := preload("res://scenes/pachinko/pachinko_game.tscn")
const BoardSwap := preload("res://tests/helpers/pachinko_board_swap.gd")

var _kept_save: RefCounted


func before_each() -> void:
	_kept_save = BoardSwap.begin()


func after_each() -> void:
	BoardSwap.end(_kept_save)


# Plays `machine`'s jackpot under way to its end: each round's attackers run out of time.
func _play_out(machine: BonusMachine) -> void:
	machine.round_clock_runs = true  # as with balls on the board
	for step in 200:
		if not machine.rounds.active():
			return
		machine.advance(2.0)


func test_the_rounds_announce_a_jackpot_again_before_its_round_one() -> void:
	var rounds := JackpotRounds.new()
	var started: Array[int] = []
	rounds.round_started.connect(func(r: int, _n: int) -> void: started.append(r))
	rounds.begin()
	assert_eq(started, [1] as Array[int], "a first jackpot opens round 1 at once")
	while rounds.active():
		rounds.end_round()
		rounds.advance(JackpotRounds.BREAK_SECONDS)
	started.clear()
	rounds.count_time(3.0)
	rounds.begin()
	assert_true(rounds.announcing(), "back to back: announced first")
	assert_true(rounds.in_break(), "nothing open while it is")
	assert_true(started.is_empty(), "round 1 waits")
	rounds.advance(JackpotRounds.AGAIN_SECONDS - 0.1)
	assert_true(started.is_empty(), "still announcing")
	rounds.advance(0.2)
	assert_eq(started, [1] as Array[int], "then round 1 opens")
	assert_false(rounds.announcing())
	assert_eq(rounds.current_round, 1)


func test_a_jackpot_long_after_the_last_opens_at_once() -> void:
	var rounds := JackpotRounds.new()
	rounds.begin()
	while rounds.active():
		rounds.end_round()
		rounds.advance(JackpotRounds.BREAK_SECONDS)
	rounds.count_time(JackpotRounds.AGAIN_WINDOW + 1.0)
	rounds.begin()
	assert_false(rounds.announcing())
	assert_false(rounds.in_break())


func test_the_attackers_clock_starts_after_the_announcement() -> void:
	var rules := PachinkoRules.new(BoardLoader.load_board(BoardSwap.FEVER).level, 1)
	rules.start_game()
	var machine := rules.bonus
	machine.rounds.begin()
	_play_out(machine)
	assert_false(machine.rounds.active(), "the first jackpot is over")
	machine.advance(1.0)
	machine.rounds.begin()  # the next spin's jackpot, a second later
	assert_false(machine.any_attacker_open(), "announced: the attacker stays shut")
	machine.advance(JackpotRounds.AGAIN_SECONDS - 0.5)
	assert_false(machine.any_attacker_open(), "its round 1 clock has not started")
	machine.advance(0.6)
	assert_true(machine.any_attacker_open(), "round 1 opens after the announcement")
	var attacker := -1
	for i in rules.level.bonus_pockets.size():
		if rules.level.bonus_pockets[i].role == BonusPocketSpec.Role.ATTACKER:
			attacker = i
	var full: float = rules.level.bonus_pockets[attacker].open_seconds
	assert_almost_eq(machine.time_left(attacker), full, 0.001, "its whole time still to run")


func test_the_banner_says_jackpot_again_and_no_summary_covers_it() -> void:
	var game := GAME.instantiate() as PachinkoGame
	add_child_autofree(game)
	await wait_process_frames(1)
	var rules := game.rules
	rules.start_game()
	var machine := rules.bonus
	machine.rounds.begin()
	_play_out(machine)
	assert_false(machine.rounds.active(), "the first jackpot is over")
	machine.advance(1.0)
	machine._on_spin_finished(PackedInt32Array([8, 8, 8]), true)  # a jackpot again
	var banner := game.bonus_view().banner
	assert_string_contains(banner.caption(), "JACKPOT AGAIN!")
	game.bonus_view()._on_jackpot_settled(120)  # the last jackpot's balls land late
	assert_string_contains(banner.caption(), "JACKPOT AGAIN!", "no JACKPOT OVER over it")
	assert_false(banner.caption().contains("JACKPOT OVER"))
	machine.advance(JackpotRounds.AGAIN_SECONDS + 0.1)
	assert_string_contains(banner.caption(), "ROUND 1 / ", "round 1 has its own moment")
