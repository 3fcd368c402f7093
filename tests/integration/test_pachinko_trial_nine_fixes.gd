extends GutTest
## Trial 9's quick fixes: the MACHINE CLEARED card waits for a Gold rush to end, the board's
## best counts the moment the machine clears, and the restart prompt names the balls the tray
## will settle at.

const GAME := preload("res://scenes/pachinko/pachinko_game.tscn")
const BoardSwap := preload("res://tests/helpers/pachinko_board_swap.gd")

var _kept_save: RefCounted


func before_each() -> void:
	_kept_save = BoardSwap.begin()


func after_each() -> void:
	BoardSwap.end(_kept_save)


func _started_game() -> PachinkoGame:
	var game := GAME.instantiate() as PachinkoGame
	add_child_autofree(game)
	await wait_process_frames(1)
	game.rules.start_game()
	return game


# Trial 9 (bug 5): the card came up as a Gold rush began and froze it at "17 s left".
func test_the_goal_reached_in_a_gold_rush_waits_for_the_rush_to_end() -> void:
	var game: PachinkoGame = await _started_game()
	var rules := game.rules
	rules.gold.start_rush()
	assert_true(rules.gold.rush_on(), "a Gold rush is on")
	rules.cup += PachinkoGoals.tray_target(rules.level)
	rules.cup_changed.emit(rules.cup)
	await wait_process_frames(1)
	assert_false(game.cleared_card().visible, "reached in a rush: no card yet")
	rules.gold.advance(GoldPins.RUSH_SECONDS + 1.0)
	assert_false(rules.gold.rush_on(), "the rush is over")
	await wait_process_frames(1)
	assert_true(game.cleared_card().visible, "the rush is over: the card comes up")


# Trial 9 (bug 3): "Won this game +7 · best none yet" beside "goal 32 cleared!".
func test_clearing_the_machine_counts_its_result_as_the_best_at_once() -> void:
	var game: PachinkoGame = await _started_game()
	var rules := game.rules
	var board_id := rules.level.board_id
	assert_eq(App.best_pachinko_balls(board_id), -1, "no best yet")
	rules.cup = PachinkoGoals.tray_target(rules.level) + 5
	rules.cup_changed.emit(rules.cup)
	await wait_process_frames(2)
	assert_true(game.cleared_card().visible, "the machine is cleared")
	var won := rules.balls_to_shoot - rules.level.cup_start_balls
	assert_gt(won, 0)
	assert_eq(App.best_pachinko_balls(board_id), won, "the board's best (its card) at once")
	assert_string_contains(game.stats_panel.shown_text(), "best +%d" % won, "and the panel's")


# Trial 9 (bug 1): "Your 79 balls go" while balls still landing took the tray to 81, then 85.
func test_the_restart_question_follows_balls_that_land_after_it() -> void:
	var game: PachinkoGame = await _started_game()
	var rules := game.rules
	rules.cup += 3  # balls won: R asks first
	var ask := InputEventAction.new()
	ask.action = &"game_restart"
	ask.pressed = true
	game._unhandled_input(ask)
	var prompt := game.restart_prompt()
	assert_true(prompt.asking(), "R asks first")
	var before := rules.balls_to_shoot
	assert_string_contains(prompt.text(), "Your %d balls go" % before)
	rules.cup += 15  # a ball in the air lands in a pocket paying 15
	await wait_process_frames(2)
	assert_true(prompt.asking(), "still asking")
	assert_string_contains(prompt.text(), "Your %d balls go" % (before + 15))


# Trial 9 (bug 2): a reach's big reels covered the aim's arc and landing circle; fired blind.
func test_the_reach_stage_fades_for_an_aim_and_the_arc_shows() -> void:
	var game: PachinkoGame = await _started_game()
	var rules := game.rules
	var stage := game.bonus_view().stage
	rules.bonus.reels.start(PackedInt32Array([3, 3, 1]), 7)
	rules.bonus.reels.advance(ReelSet.STOP_SECONDS[1] + 0.01)
	stage._process(1.0)
	assert_true(stage.is_on_stage(), "a reach is on stage")
	var aim := game.board_view.aim_preview()
	rules.begin_charge()
	rules.set_power(60.0)
	game._process(1.0 / 60.0)
	stage._process(1.0)
	aim._process(1.0)
	assert_true(aim.is_showing(), "the arc shows while aiming")
	assert_almost_eq(stage.modulate.a, ReachStage.AIMING_ALPHA, 0.01, "the reels fade for it")
