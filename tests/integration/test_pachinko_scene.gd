extends GutTest
## The game scene headless: it loads the board, the instructions gate the game, their Play
## button starts it and a drag on the flipper fires a ball drawn by the one ball layer.

const GAME := "res://scenes/pachinko/pachinko_game.tscn"


func _game() -> PachinkoGame:
	var game := (load(GAME) as PackedScene).instantiate() as PachinkoGame
	add_child_autofree(game)
	return game


func _click(game: Node, at: Vector2, pressed: bool) -> void:
	var event := InputEventMouseButton.new()
	event.button_index = MOUSE_BUTTON_LEFT
	event.pressed = pressed
	event.position = at
	game._unhandled_input(event)


func test_the_scene_starts_with_the_instructions() -> void:
	var game := _game()
	var rules := game.get("rules") as PachinkoRules
	assert_not_null(rules, "the board loaded")
	assert_eq(rules.state, PachinkoRules.State.INSTRUCTIONS)
	assert_true((game.get_node("Instructions") as Control).visible)
	assert_not_null(game.get_node_or_null("PauseMenu"), "the shell's pause menu is in")


# The card has been up long enough to be read (InstructionsPanel.READ_SECONDS).
func _let_the_card_be_read(game: PachinkoGame) -> void:
	game.instructions._process(InstructionsPanel.READ_SECONDS + 0.1)


func _play_button(game: Node) -> Button:
	return game.get_node("Instructions/Card/Margin/Box/Play") as Button


func test_the_play_button_starts_and_a_flipper_drag_fires() -> void:
	var game := _game()
	var rules := game.get("rules") as PachinkoRules
	_let_the_card_be_read(game)
	_play_button(game).pressed.emit()
	assert_eq(rules.state, PachinkoRules.State.PLAYING)
	assert_false((game.get_node("Instructions") as Control).visible)
	var launcher := game.get_node("Hud/Column/Launcher")
	launcher.emit_signal("flipper_pressed", Vector2(1000, 600))
	var motion := InputEventMouseMotion.new()
	motion.position = Vector2(1000, 540)
	game._input(motion)
	# 60 view units up, in a window whose board asks full_power_drag() for full power
	assert_almost_eq(rules.power, 60.0 * 100.0 / game.full_power_drag(), 0.01)
	var release := InputEventMouseButton.new()
	release.button_index = MOUSE_BUTTON_LEFT
	release.pressed = false
	release.position = Vector2(1000, 540)
	game._input(release)
	assert_eq(rules.ledger.shots, 1)
	assert_eq(rules.world.ball_count(), 1)
	await wait_process_frames(2)
	var balls := game.get_node("BoardView/Balls")
	assert_eq(int(balls.get("last_drawn")), 2, "the fired ball and the loaded one, one batch")


func test_the_start_charge_and_handle_keys_each_start_the_game() -> void:
	for action: StringName in [&"game_start", &"launch_charge", &"launch_handle"]:
		var game := _game()
		var rules := game.get("rules") as PachinkoRules
		var key := InputEventKey.new()
		key.physical_keycode = _first_key(action)
		key.pressed = true
		assert_true(key.is_action_pressed(action), "a key is bound to %s" % action)
		_let_the_card_be_read(game)
		game._unhandled_input(key)
		assert_eq(rules.state, PachinkoRules.State.PLAYING, "%s starts the game" % action)
		if action == &"launch_handle":
			assert_true(rules.handle.held, "and the held handle key streams at once")
		game.queue_free()


func test_the_start_line_names_a_key() -> void:
	var game := _game()
	var footer := game.get_node("Instructions/Card/Margin/Box/Footer") as Label
	assert_eq(_play_button(game).text, "Play")
	assert_string_contains(footer.text, "press Enter")


func test_a_click_elsewhere_leaves_the_card_up() -> void:
	var game := _game()
	var rules := game.get("rules") as PachinkoRules
	_let_the_card_be_read(game)
	_click(game, Vector2(300, 300), true)
	assert_eq(rules.state, PachinkoRules.State.INSTRUCTIONS, "the card is dismissed by its button")
	assert_true(game.instructions.visible)


func test_the_click_that_chose_the_board_cannot_dismiss_the_card() -> void:
	var game := _game()
	var rules := game.get("rules") as PachinkoRules
	# a click queued while the board loaded lands on the card's first frames
	_play_button(game).pressed.emit()
	var enter := InputEventKey.new()
	enter.physical_keycode = _first_key(&"game_start")
	enter.pressed = true
	game._unhandled_input(enter)
	game.launcher.flipper_pressed.emit(Vector2(1000, 600))
	assert_eq(rules.state, PachinkoRules.State.INSTRUCTIONS, "nothing in its first half second")
	_let_the_card_be_read(game)
	_play_button(game).pressed.emit()
	assert_eq(rules.state, PachinkoRules.State.PLAYING, "then its button starts the game")


func test_game_over_offers_play_again_on_the_card() -> void:
	var game := _game()
	var rules := game.get("rules") as PachinkoRules
	game.instructions.show_game_over(rules.level, rules.stats(true), 0, false)
	assert_eq(_play_button(game).text, "Play again")
	_play_button(game).pressed.emit()
	_click(game, Vector2(300, 300), true)
	assert_eq(rules.state, PachinkoRules.State.INSTRUCTIONS, "not at once, nor by a click")
	_let_the_card_be_read(game)
	_play_button(game).pressed.emit()
	assert_eq(rules.state, PachinkoRules.State.PLAYING)


func _first_key(action: StringName) -> Key:
	for event in InputMap.action_get_events(action):
		var key := event as InputEventKey
		if key != null:
			return key.physical_keycode
	return KEY_NONE


func test_the_grip_is_the_flipper_and_the_rest_is_not() -> void:
	var game := _game()
	var launcher := game.get_node("Hud/Column/Launcher")
	var grip: Vector2 = launcher.get("PIVOT") + Vector2(-float(launcher.get("LEVER_LENGTH")), 0)
	assert_true(launcher.is_on_flipper(grip))
	assert_false(launcher.is_on_flipper(Vector2(5, 5)))


func test_holding_the_charge_key_fires_on_release() -> void:
	var game := _game()
	var rules := game.get("rules") as PachinkoRules
	rules.start_game()
	var key := InputEventKey.new()
	key.physical_keycode = KEY_SPACE
	key.pressed = true
	assert_true(key.is_action_pressed(&"launch_charge"), "Space is bound to launch_charge")
	game._unhandled_input(key)
	assert_true(rules.drawing)
	game._process(0.5)
	assert_almost_eq(rules.power, PachinkoRules.CHARGE_PER_SECOND * 0.5, 0.01)
	var up := InputEventKey.new()
	up.physical_keycode = KEY_SPACE
	up.pressed = false
	game._unhandled_input(up)
	assert_eq(rules.ledger.shots, 1, "letting go fired the ball")
	assert_eq(rules.power, 0.0)


func test_the_left_stick_pulled_down_draws_back_and_fires_when_let_go() -> void:
	var game := _game()
	var rules := game.get("rules") as PachinkoRules
	rules.start_game()
	var stick := InputEventJoypadMotion.new()
	stick.axis = JOY_AXIS_LEFT_Y
	stick.axis_value = 1.0
	game._unhandled_input(stick)
	assert_true(rules.drawing, "pulling the stick down draws the flipper back")
	assert_eq(rules.power, 100.0)
	stick.axis_value = 0.0
	game._unhandled_input(stick)
	assert_eq(rules.ledger.shots, 1, "letting the stick go fired")


func test_a_broken_board_path_shows_the_problem() -> void:
	App.request_board("pachinko", "res://levels/pachinko/does_not_exist.board")
	var game := _game()
	App.request_board("pachinko", "res://levels/pachinko/classic.board")
	assert_push_error("does not exist")
	assert_null(game.get("rules"), "nothing to play")
	var title := game.get_node("Instructions/Card/Margin/Box/Title") as Label
	assert_eq(title.text, "This board could not be loaded")


func test_restart_from_the_pause_menu_sets_up_a_fresh_board() -> void:
	var game := _game()
	var first := game.get("rules") as PachinkoRules
	first.start_game()
	first.fire(60.0)
	game.get_node("PauseMenu").emit_signal("restart_requested")
	var second := game.get("rules") as PachinkoRules
	assert_ne(second, first, "new rules")
	assert_eq(second.state, PachinkoRules.State.INSTRUCTIONS)
	assert_eq(second.world.ball_count(), 0)
	assert_true((game.get_node("Instructions") as Control).visible)
