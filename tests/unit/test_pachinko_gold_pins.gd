extends GutTest
## Gold pins in the rules: the seed fixes the sets, a lit pin counts once and adds a ball to
## the cup, the last one out gives the set's prize (a Gold spin on a reel machine, a Gold
## rush elsewhere) and lights a new set. The pin hits are the world's own signal, sent here
## directly, so each case is exact and needs no ball to roll.

const CLASSIC := "res://levels/pachinko/classic.board"
const FEVER := "res://levels/pachinko/fever.board"


func _rules(path: String = CLASSIC, rng_seed: int = 1) -> PachinkoRules:
	var level := BoardLoader.load_board(path).level.duplicate(true) as BoardLevel
	level.cup_start_balls = 10
	var rules := PachinkoRules.new(level, rng_seed)
	rules.start_game()
	return rules


func _put_out_all(rules: PachinkoRules, ball: int) -> void:
	for pin in rules.gold.pins:
		rules.world.pin_hit.emit(ball, pin, 100.0)


func test_the_same_seed_lights_the_same_pins() -> void:
	var a := _rules(CLASSIC, 7)
	var b := _rules(CLASSIC, 7)
	var c := _rules(CLASSIC, 8)
	assert_eq(a.gold.pins, b.gold.pins)
	assert_ne(a.gold.pins, c.gold.pins, "another seed, another set")
	assert_between(a.gold.pins.size(), 6, 8)


func test_a_lit_pin_adds_one_ball_once() -> void:
	var rules := _rules()
	var ball := rules.fire(50.0)
	var pin := rules.gold.pins[0]
	var shootable := rules.balls_to_shoot
	rules.world.pin_hit.emit(ball, pin, 100.0)
	assert_eq(rules.balls_to_shoot, shootable + 1, "a gold pin adds a ball")
	rules.world.pin_hit.emit(ball, pin, 100.0)
	assert_eq(rules.balls_to_shoot, shootable + 1, "the same pin again adds nothing")
	assert_eq(rules.gold.pins_out, 1)
	assert_eq(rules.gold.left(), rules.gold.pins.size() - 1)
	assert_true(rules.accounting_ok())


func test_a_plain_pin_adds_nothing() -> void:
	var rules := _rules()
	var ball := rules.fire(50.0)
	var plain := 0
	while rules.gold.pins.has(plain):
		plain += 1
	var shootable := rules.balls_to_shoot
	rules.world.pin_hit.emit(ball, plain, 100.0)
	assert_eq(rules.balls_to_shoot, shootable)


func test_the_last_pin_gives_a_gold_rush_and_a_new_set_without_reels() -> void:
	var rules := _rules()
	watch_signals(rules.gold)
	var first := rules.gold.pins.duplicate()
	_put_out_all(rules, rules.fire(50.0))
	assert_signal_emitted_with_parameters(rules.gold, "set_cleared", [1, false])
	assert_true(rules.gold.rush_on(), "no reels: a Gold rush")
	assert_eq(rules.gold.set_number, 2)
	assert_eq(rules.gold.left(), rules.gold.pins.size(), "a new set lights, all lit")
	assert_ne(rules.gold.pins, first)
	assert_eq(rules.stats()["gold_sets"], 1)


func test_a_gold_rush_pays_double_then_ends() -> void:
	var rules := _rules()
	rules.gold.start_rush()
	var ball := rules.fire(50.0)
	var cup := rules.cup
	var payout: int = rules.level.pockets[0].payout
	rules.world.remove_ball(ball)
	rules.world.ball_captured.emit(ball, 0)
	assert_eq(rules.cup, cup + payout * GoldPins.RUSH_FACTOR)
	rules.gold.advance(GoldPins.RUSH_SECONDS + 0.1)
	assert_false(rules.gold.rush_on(), "the rush ends after its seconds")
	assert_true(rules.accounting_ok())


func test_the_last_pin_gives_a_gold_spin_on_a_reel_machine() -> void:
	var rules := _rules(FEVER)
	watch_signals(rules.gold)
	_put_out_all(rules, rules.fire(50.0))
	assert_signal_emitted_with_parameters(rules.gold, "set_cleared", [1, true])
	assert_false(rules.gold.rush_on())
	assert_eq(rules.bonus.queued_spins(), 1, "a Gold spin waits for the reels")
	rules.bonus.advance(0.1)
	assert_true(rules.bonus.reels.is_reach(), "a Gold spin is always a reach")


func test_gold_spins_land_a_jackpot_about_one_in_three() -> void:
	var level := BoardLoader.load_board(FEVER).level
	var machine := BonusMachine.new(level, BoardWorldFactory.build(level), 3)
	var jackpots := 0
	for i in 300:
		assert_true(machine.grant_gold_spin())
		machine.advance(0.01)
		assert_true(machine.reels.is_reach())
		if machine.reels.is_jackpot():
			jackpots += 1
		machine.reels.stopped = ReelSet.REELS
		machine.reels.elapsed = 100.0
	assert_between(jackpots, 70, 130, "about 100 of 300")


func test_a_new_game_lights_a_fresh_first_set() -> void:
	var rules := _rules()
	_put_out_all(rules, rules.fire(50.0))
	rules.gold.light_first_set()
	assert_eq(rules.gold.set_number, 1)
	assert_false(rules.gold.rush_on(), "a new game ends the rush")
