extends GutTest
## Each machine's goal (PachinkoGoals): filling the tray to its target clears the machine,
## once, with a large win card (Next machine / Keep playing / Menu); the clear is saved and
## the board's card says so. The targets are set from `--sessions=20 --seed=1` (peak_won).

const GAME := preload("res://scenes/pachinko/pachinko_game.tscn")
const BoardSwap := preload("res://tests/helpers/pachinko_board_swap.gd")

var _kept_save: RefCounted


func before_each() -> void:
	_kept_save = BoardSwap.begin()


func after_each() -> void:
	BoardSwap.end(_kept_save)


func _win(rules: PachinkoRules, balls: int) -> void:
	rules.cup += balls
	rules.cup_changed.emit(rules.cup)


func test_every_machine_has_a_goal_above_its_start() -> void:
	for result in BoardLoader.list_boards(BoardLevel.Kind.PACHINKO):
		var level := result.level
		var target := PachinkoGoals.tray_target(level)
		assert_gt(target, level.cup_start_balls, "%s: %d" % [level.board_id, target])
		assert_string_contains(PachinkoGoals.words(level), "Fill the tray: %d balls" % target)


func test_filling_the_tray_clears_the_machine_once_with_a_win_card() -> void:
	var game := GAME.instantiate() as PachinkoGame
	add_child_autofree(game)
	await wait_process_frames(1)
	var rules := game.rules
	rules.start_game()
	var target := PachinkoGoals.tray_target(rules.level)
	var board := rules.level.board_id
	_win(rules, target - rules.balls_to_shoot - 1)
	assert_false(game.cleared_card().visible, "one short: not yet")
	assert_false(App.has_cleared_pachinko(board))
	game.cup.pour(6)  # still falling when the goal is reached
	_win(rules, 1)
	assert_true(game.cleared_card().visible, "the tray is full: the win card")
	assert_eq(game.cup.count(), rules.balls_to_shoot, "the tray shows the card's count")
	assert_string_contains(game.cleared_card().text(), "CLEARED")
	var card := game.instructions.get_node("Card/Margin/Box/Body") as RichTextLabel
	assert_string_contains(card.get_parsed_text(), "Goal: Fill the tray", "the start card says it")
	assert_true(App.has_cleared_pachinko(board), "remembered for the board's card")
	game.cleared_card().dismiss()  # Keep playing
	_win(rules, 5)
	assert_false(game.cleared_card().visible, "once a game")
	assert_eq(rules.state, PachinkoRules.State.PLAYING, "and the game goes on")
	var result := BoardLoader.load_board("res://levels/pachinko/fever.board")
	App.record_pachinko_balls(board, 40)
	assert_string_contains(LevelSelectWords.best_text(result, "pachinko"), "Cleared!")


func _charge_key(pressed: bool) -> InputEventAction:
	var event := InputEventAction.new()
	event.action = &"launch_charge"
	event.pressed = pressed
	return event


func test_no_shot_fires_and_no_ball_moves_while_the_win_card_is_up() -> void:
	# Trial 5: shots fired behind the card, landed hidden and paid
	var game := GAME.instantiate() as PachinkoGame
	add_child_autofree(game)
	await wait_process_frames(1)
	var rules := game.rules
	rules.start_game()
	_win(rules, PachinkoGoals.tray_target(rules.level) - rules.balls_to_shoot)
	assert_true(game.cleared_card().visible)
	var shots := rules.ledger.shots
	var world := rules.world.state_hash()
	game._unhandled_input(_charge_key(true))
	for frame in 90:
		game._process(1.0 / 60.0)
	game._unhandled_input(_charge_key(false))
	game._on_flipper_pressed(Vector2.ZERO)
	for frame in 30:
		game._process(1.0 / 60.0)
	assert_eq(rules.ledger.shots, shots, "no shot behind the card")
	assert_eq(rules.world.state_hash(), world, "the board waits for the player")


func test_next_machine_is_the_next_board_in_the_list() -> void:
	var boards := BoardLoader.list_boards(BoardLevel.Kind.PACHINKO)
	var first := boards[0].level
	assert_eq(MachineGoal.next_board_path(first), boards[1].path)
	assert_eq(MachineGoal.next_board_path(boards[boards.size() - 1].level), boards[0].path)


func test_the_panel_shows_the_goal_and_the_tray_now_during_play() -> void:
	var game := GAME.instantiate() as PachinkoGame
	add_child_autofree(game)
	await wait_process_frames(1)
	var rules := game.rules
	rules.start_game()
	var target := PachinkoGoals.tray_target(rules.level)
	await wait_process_frames(2)
	var shown := game.stats_panel.shown_text()
	assert_string_contains(shown, "Balls %d · goal %d" % [rules.balls_to_shoot, target])
	_win(rules, 7)
	await wait_process_frames(2)
	shown = game.stats_panel.shown_text()
	assert_string_contains(shown, "Balls %d · goal %d" % [rules.balls_to_shoot, target])
	_win(rules, target)
	await wait_process_frames(2)
	assert_string_contains(game.stats_panel.shown_text(), "goal %d cleared!" % target)


func test_the_goal_line_fits_one_line_of_the_column() -> void:
	for line in StatsPanel.lines_for({"shots": 243, "balls_left": 1234}, 1200, 1350, false):
		var plain := line.replace("[b]", "").replace("[/b]", "")
		assert_lte(plain.length(), 32, "'%s' fits one line of the column" % plain)


func test_the_win_cards_buttons_wear_the_games_theme() -> void:
	var card := MachineClearedCard.new()
	add_child_autofree(card)
	var ui_theme := load("res://scenes/menu/ui_theme.tres") as Theme
	var themed := ui_theme.get_stylebox(&"normal", &"Button")
	for button in card.buttons():
		assert_eq(button.get_theme_stylebox(&"normal"), themed, button.text)


func _restart_key() -> InputEventAction:
	var event := InputEventAction.new()
	event.action = &"game_restart"
	event.pressed = true
	return event


func test_r_asks_nothing_and_keeps_the_game_while_the_win_card_is_up() -> void:
	# Trial 5: "New game? ..." showed over the MACHINE CLEARED! card; the card's own buttons
	# decide, so R does nothing, and a question already up when the card comes goes
	var game := GAME.instantiate() as PachinkoGame
	add_child_autofree(game)
	await wait_process_frames(1)
	var rules := game.rules
	rules.start_game()
	_win(rules, 5)  # under the goal: the game goes on
	game._unhandled_input(_restart_key())
	assert_true(game.restart_prompt().asking(), "balls won: R asks first")
	_win(rules, PachinkoGoals.tray_target(rules.level) - rules.balls_to_shoot)
	assert_true(game.cleared_card().visible)
	assert_false(game.restart_prompt().asking(), "the question goes under the card")
	for press in 2:
		game._unhandled_input(_restart_key())
	assert_false(game.restart_prompt().asking(), "R asks nothing over the card")
	assert_eq(game.rules, rules, "and starts no new game")
	assert_true(game.cleared_card().visible, "the card stays for its buttons")


func test_the_win_cards_board_chooser_button_says_where_it_goes() -> void:
	# trial 8, bug 8: "Menu" opened the board chooser, and the player wanted the main menu;
	# the button says what the pause menu's button to the same place says
	var card := MachineClearedCard.new()
	add_child_autofree(card)
	var texts: Array[String] = []
	for button in card.buttons():
		texts.append(button.text)
	assert_eq(texts, ["Next machine", "Keep playing", "Other boards"] as Array[String])
	var pause := (load("res://scenes/common/pause_menu.tscn") as PackedScene).instantiate()
	var to_boards := pause.get_node("Dim/Center/Panel/Box/MenuButton") as Button
	assert_eq(card.buttons()[2].text, to_boards.text, "the pause menu's words for the chooser")
	pause.free()
