extends GutTest
## The four faults of issue 17, each pinned by a test that fails without its fix: power
## climbing after a release lost to the pause menu, two balls wedged in a 22 px pocket,
## the gutter's bounce count (the chapter drains on the 7th), and the payout ratio
## counting weak shots that rolled back.

const CLASSIC := "res://levels/pachinko/classic.board"
const GAME := "res://scenes/pachinko/pachinko_game.tscn"


func _playing() -> PachinkoRules:
	var level := BoardLoader.load_board(CLASSIC).level.duplicate(true) as BoardLevel
	var rules := PachinkoRules.new(level, 1)
	rules.start_game()
	return rules


func _key(pressed: bool) -> InputEventKey:
	var key := InputEventKey.new()
	key.physical_keycode = KEY_SPACE
	key.pressed = pressed
	return key


func _pointer(pressed: bool, at: Vector2) -> InputEventMouseButton:
	var button := InputEventMouseButton.new()
	button.button_index = MOUSE_BUTTON_LEFT
	button.pressed = pressed
	button.position = at
	return button


# (1) Hold Space, pause, let go while paused, resume: nothing may charge or fire.
func test_a_key_let_go_during_the_pause_does_not_keep_charging() -> void:
	var game := (load(GAME) as PackedScene).instantiate() as PachinkoGame
	add_child_autofree(game)
	var rules := game.get("rules") as PachinkoRules
	rules.start_game()
	game._unhandled_input(_key(true))
	game._process(0.2)
	assert_almost_eq(
		rules.power, PachinkoRules.CHARGE_PER_SECOND * 0.2, 0.01, "charging before the pause"
	)
	var pause := game.get_node("PauseMenu")
	pause.open()
	# The release goes to a paused game: Godot does not deliver it to _unhandled_input.
	pause.close()
	game._process(2.0)
	assert_eq(rules.power, 0.0, "no key is held: the power stays at zero")
	assert_false(rules.drawing)
	assert_eq(rules.ledger.shots, 0, "nothing was fired")
	game._unhandled_input(_key(true))
	assert_true(rules.drawing, "the next press is taken")
	game._process(0.25)
	game._unhandled_input(_key(false))
	assert_eq(rules.ledger.shots, 1, "and its release fires at its own power")


func test_a_drag_let_go_during_the_pause_does_not_follow_the_mouse_after() -> void:
	var game := (load(GAME) as PackedScene).instantiate() as PachinkoGame
	add_child_autofree(game)
	var rules := game.get("rules") as PachinkoRules
	rules.start_game()
	var launcher := game.get_node("Hud/Column/Launcher")
	launcher.emit_signal("flipper_pressed", Vector2(1000, 600))
	var pause := game.get_node("PauseMenu")
	pause.open()
	pause.close()
	var motion := InputEventMouseMotion.new()
	motion.position = Vector2(1000, 520)
	game._input(motion)
	assert_eq(rules.power, 0.0, "the mouse moves with no button held: no drawback")
	game._input(_pointer(false, motion.position))
	assert_eq(rules.ledger.shots, 0, "a stray release fires nothing")
	launcher.emit_signal("flipper_pressed", Vector2(1000, 600))
	motion.position = Vector2(1000, 550)
	game._input(motion)
	# 50 view units of drag, in a window whose board asks full_power_drag() for full power
	var drawn := 50.0 * LaunchPower.MAX_POWER / game.full_power_drag()
	assert_almost_eq(rules.power, drawn, 0.01, "a new drag works")
	game._input(_pointer(false, motion.position))
	assert_eq(rules.ledger.shots, 1)


# (2) Two balls side by side in a 22 px pocket wedge above the special pin; both must be
# caught within a second, not after the stuck-ball nudges (3 s and more).
func test_two_balls_wedged_in_a_pocket_are_caught_quickly() -> void:
	var rules := _playing()
	var spec: PocketSpec = rules.level.pockets[1]
	var y := spec.position.y + spec.depth - spec.width * 0.5
	var left := rules.place_ball(spec.position + Vector2(-5.2, y - spec.position.y))
	var right := rules.place_ball(spec.position + Vector2(5.2, y - spec.position.y))
	var paid_before := rules.ledger.paid
	for i in int(1.0 / rules.step_seconds()):
		rules.step()
	assert_false(rules.world.has_ball(left), "the left ball was caught")
	assert_false(rules.world.has_ball(right), "the right ball was caught")
	assert_eq(rules.ledger.pocket_hits[1], 2, "both count for the pocket")
	assert_eq(rules.ledger.paid - paid_before, spec.payout * 2)
	assert_eq(rules.ledger.nudges, 0, "no nudge was needed")
	assert_true(rules.accounting_ok())


func test_a_ball_falling_past_a_pocket_is_not_caught() -> void:
	var rules := _playing()
	var spec: PocketSpec = rules.level.pockets[0]
	var id := rules.place_ball(spec.position + Vector2(spec.width, -40.0))
	for i in int(0.3 / rules.step_seconds()):
		rules.step()
	assert_true(rules.world.has_ball(id), "outside the cup: still in play")
	assert_eq(rules.ledger.won, 0)


# (3) The chapter: `if (ball.gutterBounce++ > 5) destroyBall(ball)` drains on the 7th bounce.
# Each bounce here is a fresh 300 px/s drop onto the bottom of the ring, so every one counts.
func test_the_gutter_drains_on_the_seventh_bounce_like_the_chapter() -> void:
	var rules := _playing()
	var level := rules.level
	assert_eq(level.gutter_bounces, 7)
	var above := level.ring_center + Vector2(0, level.ring_radius - level.ball_radius - 12.0)
	var id := rules.place_ball(above, Vector2(0, 300))
	var hits := [0]
	rules.world.ring_hit.connect(
		func(ball: int, _speed: float) -> void: hits[0] += 1 if ball == id else 0
	)
	var seen := 0
	for i in int(4.0 / rules.step_seconds()):
		rules.step()
		if not rules.world.has_ball(id):
			break
		if hits[0] > seen:
			seen = hits[0]
			rules.world.set_ball_position(id, above)
			rules.world.set_ball_velocity(id, Vector2(0, 300))
	assert_false(rules.world.has_ball(id), "the gutter took the ball")
	assert_eq(hits[0], 7, "six bounces survived, the seventh drains")
	for path in DirAccess.get_files_at("res://levels/pachinko"):
		if path.ends_with(".board"):
			var board := BoardLoader.load_board("res://levels/pachinko/" + path).level
			assert_eq(board.gutter_bounces, 7, "%s drains on the 7th bounce" % path)


# (4) Shots that rolled back cost nothing and must not dilute the return.
func test_the_payout_ratio_leaves_out_rolled_back_shots() -> void:
	var rules := _playing()
	# A shot that rolled back: a ball at rest in the rail rolls down to the stopper.
	var weak := rules.place_ball(LaunchRail.launch_position(rules.level))
	rules.ledger.shots += 1  # it stands for a shot that rolled back
	for i in int(6.0 / rules.step_seconds()):
		rules.step()
		if not rules.world.has_ball(weak):
			break
	assert_eq(rules.ledger.returned, 1, "the weak shot came back")
	var spec: PocketSpec = rules.level.pockets[0]
	rules.place_ball(PocketStamp.special_position(spec) + Vector2(0, -spec.width * 0.5))
	rules.ledger.shots += 1  # the placed ball stands for one shot that reached the field
	for i in int(1.0 / rules.step_seconds()):
		rules.step()
	assert_eq(rules.ledger.won, 1)
	assert_eq(rules.ledger.shots, 2)
	assert_almost_eq(rules.ledger.payout_ratio(), float(spec.payout), 0.001)
	assert_almost_eq(float(rules.stats()["payout_ratio"]), float(spec.payout), 0.001)
