extends GutTest
## Pachinko payouts as the player sees them: a caught ball pays its pocket's balls into the
## cup, the win names the pocket and where it is, the next ball loads, and the side panel's
## "this game" figures start again with each game. The catches are the world's own signal,
## sent here directly, so each case is exact and needs no ball to roll.

const CLASSIC := "res://levels/pachinko/classic.board"
const HANAMI := "res://levels/pachinko/hanami.board"


func _rules(path: String = CLASSIC, cup_balls: int = 10) -> PachinkoRules:
	var level := BoardLoader.load_board(path).level.duplicate(true) as BoardLevel
	level.cup_start_balls = cup_balls
	var rules := PachinkoRules.new(level, 1)
	rules.start_game()
	return rules


# A ball in play, as the launcher fires it; its id.
func _shot(rules: PachinkoRules) -> int:
	return rules.fire(50.0)


# The world catches ball `id` in world pocket `pocket`, as it does: the ball leaves, then
# the world says where it went.
func _catch(rules: PachinkoRules, id: int, pocket: int) -> void:
	rules.world.remove_ball(id)
	rules.world.ball_captured.emit(id, pocket)


func test_a_catch_pays_its_pocket_into_the_cup() -> void:
	var rules := _rules()
	watch_signals(rules)
	var last := rules.level.pockets.size() - 1
	var spec: PocketSpec = rules.level.pockets[last]
	spec.payout = 7
	var id := _shot(rules)
	var cup := rules.cup
	_catch(rules, id, last)
	assert_eq(rules.cup, cup + 7)
	assert_signal_emitted_with_parameters(rules, "ball_won", [id, last, 7, spec.position])
	assert_signal_emitted_with_parameters(rules, "cup_changed", [cup + 7])
	assert_eq(rules.ledger.pocket_hits[last], 1, "booked to the pocket that caught it")
	assert_eq(rules.ledger.pocket_payouts[last], 7)
	assert_eq(rules.balls_in_play(), 0, "the ball left play")
	assert_true(rules.accounting_ok())


func test_the_first_pocket_pays_too() -> void:
	var rules := _rules()
	var spec: PocketSpec = rules.level.pockets[0]
	var id := _shot(rules)
	var cup := rules.cup
	_catch(rules, id, 0)
	assert_eq(rules.cup, cup + spec.payout)
	assert_eq(rules.ledger.pocket_hits[0], 1)
	assert_eq(rules.stats()["payouts"], spec.payout)


func test_a_pocket_set_below_nothing_pays_nothing() -> void:
	var rules := _rules()
	rules.level.pockets[1].payout = -4
	var id := _shot(rules)
	var cup := rules.cup
	_catch(rules, id, 1)
	assert_eq(rules.cup, cup, "the cup never shrinks on a win")
	assert_eq(rules.ledger.paid, 0)
	assert_true(rules.accounting_ok())


func test_a_catch_by_no_pocket_of_the_board_pays_nothing_but_ends_the_ball() -> void:
	var rules := _rules()
	watch_signals(rules)
	var id := _shot(rules)
	var cup := rules.cup
	var past := rules.level.pockets.size()
	_catch(rules, id, past)
	assert_eq(rules.cup, cup)
	assert_signal_emitted_with_parameters(rules, "ball_won", [id, past, 0, Vector2.ZERO])
	assert_eq(rules.ledger.won, 1)
	assert_true(rules.accounting_ok())


func test_a_catch_by_pocket_minus_one_pays_nothing() -> void:
	var rules := _rules()
	watch_signals(rules)
	var id := _shot(rules)
	var cup := rules.cup
	_catch(rules, id, -1)
	assert_eq(rules.cup, cup, "not the last pocket's payout")
	assert_signal_emitted_with_parameters(rules, "ball_won", [id, -1, 0, Vector2.ZERO])


func test_the_first_bonus_pocket_is_where_the_win_shows() -> void:
	var rules := _rules(HANAMI)
	watch_signals(rules)
	var spec: BonusPocketSpec = rules.level.bonus_pockets[0]
	var id := _shot(rules)
	_catch(rules, id, rules.level.pockets.size())
	var won: Array = get_signal_parameters(rules, "ball_won")
	assert_eq(won[3], spec.position, "the first bonus pocket's own place")
	assert_eq(rules.ledger.pocket_hits[rules.level.pockets.size()], 1)


func test_a_ball_is_paid_once() -> void:
	var rules := _rules()
	var id := _shot(rules)
	var cup := rules.cup
	_catch(rules, id, 0)
	_catch(rules, id, 0)
	assert_eq(rules.cup, cup + rules.level.pockets[0].payout, "a second catch of it pays nothing")
	assert_eq(rules.ledger.won, 1)
	_catch(rules, 999, 0)
	assert_eq(rules.ledger.won, 1, "nor does a ball that was never in play")


func test_a_bonus_pocket_pays_its_own_payout_where_it_is() -> void:
	var rules := _rules(HANAMI)
	watch_signals(rules)
	var index := -1
	for i in rules.level.bonus_pockets.size():
		if rules.level.bonus_pockets[i].payout > 0 and index < 0:
			index = i
	assert_gte(index, 0, "hanami has a paying bonus pocket")
	var spec: BonusPocketSpec = rules.level.bonus_pockets[index]
	var world_id := rules.level.pockets.size() + index
	var id := _shot(rules)
	var cup := rules.cup
	_catch(rules, id, world_id)
	assert_eq(rules.cup, cup + spec.payout)
	assert_signal_emitted_with_parameters(
		rules, "ball_won", [id, world_id, spec.payout, spec.position]
	)
	assert_eq(rules.ledger.pocket_hits[world_id], 1)


func test_a_win_with_the_cup_empty_loads_the_next_ball() -> void:
	var rules := _rules(CLASSIC, 1)
	var id := _shot(rules)
	assert_eq(rules.cup, 0)
	assert_false(rules.loaded)
	_catch(rules, id, 0)
	assert_true(rules.loaded, "a paid ball goes straight into the launcher")
	assert_eq(rules.cup, rules.level.pockets[0].payout - 1)
	assert_eq(rules.state, PachinkoRules.State.PLAYING)


func test_the_last_ball_caught_for_nothing_ends_the_game() -> void:
	var rules := _rules(CLASSIC, 1)
	watch_signals(rules)
	var id := _shot(rules)
	_catch(rules, id, rules.level.pockets.size())
	assert_eq(rules.state, PachinkoRules.State.GAME_OVER)
	assert_signal_emitted(rules, "game_ended")


func test_this_games_figures_start_again_with_each_game() -> void:
	var rules := _rules(CLASSIC, 1)
	var payout: int = rules.level.pockets[0].payout
	var id := _shot(rules)
	_catch(rules, id, 0)
	var game := rules.stats(true)
	assert_eq(game["game_payouts"], payout)
	assert_eq(game["game_shots"], 1)
	assert_eq(game["game_hits"], 1)
	assert_eq(game["cup"], payout - 1)
	assert_eq(game["loaded"], true)
	assert_eq(game["in_play"], 0)
	assert_eq(game["balls_left"], payout)
	assert_eq(game["accounting_ok"], true)
	assert_true(game.has("jackpots"), "the bonus counters are there")
	# play the game out: every ball drains
	while rules.loaded:
		var ball := _shot(rules)
		rules.world.remove_ball(ball)
		rules.world.ball_drained.emit(ball)
	assert_eq(rules.state, PachinkoRules.State.GAME_OVER)
	assert_eq(rules.stats(true)["balls_left"], 0, "nothing loaded, nothing in the cup")
	assert_true(rules.start_game())
	var fresh := rules.stats(true)
	assert_eq(fresh["game_payouts"], 0, "a new game has paid nothing yet")
	assert_eq(fresh["game_shots"], 0)
	assert_eq(fresh["game_hits"], 0)
	assert_eq(fresh["payouts"], 0, "this game's own pocket figures")
	var session := rules.stats()
	assert_eq(session["payouts"], payout, "the session keeps every game's")
	assert_eq(session["game_payouts"], 0)
	assert_eq(session["shots"], payout + 1)


func test_the_accounting_check_sees_a_ball_the_rules_do_not_know() -> void:
	var rules := _rules()
	assert_true(rules.accounting_ok())
	var stray := rules.world.spawn_ball(Vector2(300, 300), Vector2.ZERO, 5.0)
	assert_gte(stray, 0)
	assert_false(rules.accounting_ok(), "a ball in the world the rules lost track of")
	rules.world.remove_ball(stray)
	rules.ledger.given += 1
	assert_false(rules.accounting_ok(), "a ball given that is nowhere")
	assert_false(rules.stats()["accounting_ok"])
