extends GutTest
## A jackpot round's clock runs only while the player is at it (issue 41, trial 7): an open
## attacker's seconds wait while no ball is on the board and nothing is being shot, and run
## again once the handle streams or a shot is drawn. A real machine ends a round on time;
## a player reading the screen must not lose one.

const FEVER := "res://levels/pachinko/fever.board"


func _rules_in_a_round() -> PachinkoRules:
	var level := BoardLoader.load_board(FEVER).level
	var rules := PachinkoRules.new(level, 1)
	rules.start_game()
	rules.bonus.rounds.begin()
	return rules


# `seconds` of play a frame at a time (one advance call runs a few frames at most).
func _play(rules: PachinkoRules, seconds: float) -> void:
	for frame in int(seconds * 60.0):
		rules.advance(1.0 / 60.0)


func _attacker(rules: PachinkoRules) -> int:
	for i in rules.level.bonus_pockets.size():
		if rules.level.bonus_pockets[i].role == BonusPocketSpec.Role.ATTACKER:
			return i
	return -1


func test_the_round_waits_while_nobody_shoots() -> void:
	var rules := _rules_in_a_round()
	var attacker := _attacker(rules)
	assert_true(rules.bonus.is_open(attacker), "the round opened the attacker")
	var before := rules.bonus.time_left(attacker)
	_play(rules, 5.0)
	assert_eq(rules.balls_in_play(), 0)
	assert_almost_eq(rules.bonus.time_left(attacker), before, 1e-6, "no ball, no shot: waits")
	assert_true(rules.bonus.is_open(attacker))


func test_the_round_runs_while_the_handle_streams() -> void:
	var rules := _rules_in_a_round()
	var attacker := _attacker(rules)
	var before := rules.bonus.time_left(attacker)
	rules.handle.set_power(80.0)
	rules.handle.grip()
	_play(rules, 2.0)
	assert_lt(rules.bonus.time_left(attacker), before - 1.5, "streaming: the clock runs")


func test_the_round_runs_while_a_shot_is_drawn_and_its_ball_flies() -> void:
	var rules := _rules_in_a_round()
	var attacker := _attacker(rules)
	var before := rules.bonus.time_left(attacker)
	rules.begin_charge()
	_play(rules, 0.5)
	assert_lt(rules.bonus.time_left(attacker), before - 0.4, "drawing a shot counts")
	rules.set_power(70.0)
	assert_gte(rules.release(), 0, "fired")
	var fired_at := rules.bonus.time_left(attacker)
	_play(rules, 0.5)
	assert_gt(rules.balls_in_play(), 0)
	assert_lt(rules.bonus.time_left(attacker), fired_at - 0.4, "a ball on the board counts")
