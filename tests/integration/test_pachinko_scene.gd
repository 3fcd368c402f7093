extends GutTest
## The game scene headless: it loads the board, the instructions gate the game, a click
## starts it and a drag on the flipper fires a ball drawn by the one ball layer.

const GAME := "res://scenes/pachinko/pachinko_game.tscn"


func _game() -> Control:
	var game := (load(GAME) as PackedScene).instantiate() as Control
	add_child_autofree(game)
	return game


func _click(game: Node, at: Vector2, pressed: bool) -> void:
	var event := InputEventMouseButton.new()
	event.button_index = MOUSE_BUTTON_LEFT
	event.pressed = pressed
	event.position = at
	game.call("_unhandled_input", event)


func test_the_scene_starts_with_the_instructions() -> void:
	var game := _game()
	var rules := game.get("rules") as PachinkoRules
	assert_not_null(rules, "the board loaded")
	assert_eq(rules.state, PachinkoRules.State.INSTRUCTIONS)
	assert_true((game.get_node("Instructions") as Control).visible)
	assert_not_null(game.get_node_or_null("PauseMenu"), "the shell's pause menu is in")


func test_a_click_starts_and_a_flipper_drag_fires() -> void:
	var game := _game()
	var rules := game.get("rules") as PachinkoRules
	_click(game, Vector2(300, 300), true)
	assert_eq(rules.state, PachinkoRules.State.PLAYING)
	assert_false((game.get_node("Instructions") as Control).visible)
	var launcher := game.get_node("Hud/Column/Launcher")
	launcher.emit_signal("flipper_pressed", Vector2(1000, 600))
	var motion := InputEventMouseMotion.new()
	motion.position = Vector2(1000, 540)
	game.call("_input", motion)
	assert_almost_eq(rules.power, 60.0, 0.01)
	var release := InputEventMouseButton.new()
	release.button_index = MOUSE_BUTTON_LEFT
	release.pressed = false
	release.position = Vector2(1000, 540)
	game.call("_input", release)
	assert_eq(rules.ledger.shots, 1)
	assert_eq(rules.world.ball_count(), 1)
	await wait_process_frames(2)
	var balls := game.get_node("BoardView/Balls")
	assert_eq(int(balls.get("last_drawn")), 2, "the fired ball and the loaded one, one batch")
