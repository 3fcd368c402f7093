extends GutTest
## The last balls' slow motion: a ball heading into a pocket mouth is seen coming, the clock
## slows only when the player has few balls left, and it always comes back to full speed
## (after the catch, after MAX_HOLD, at game over). The game runs the same fixed steps, so a
## game played through slow motion has the state hash of one played without it.

const CLASSIC := "res://levels/pachinko/classic.board"
const GAME := "res://scenes/pachinko/pachinko_game.tscn"
const FRAME := 1.0 / 60.0


class RecordingBank:
	extends SoundBank
	var heard: Array[StringName] = []

	func play(sound: StringName, _volume_db: float = 0.0, _pitch: float = 1.0) -> bool:
		heard.append(sound)
		return true


func _rules() -> PachinkoRules:
	var rules := PachinkoRules.new(load(CLASSIC) as BoardLevel, 1)
	rules.start_game()
	return rules


# Leaves the player `left` balls to shoot (the cup emptied by hand: a view test).
func _leave(rules: PachinkoRules, left: int) -> void:
	rules.cup = maxi(left - 1, 0)


# A ball just above the first pocket's mouth, falling into it.
func _drop_into_pocket(rules: PachinkoRules) -> int:
	var mouth := rules.level.pockets[0].position
	return rules.place_ball(mouth + Vector2(0.0, -18.0), Vector2(0.0, 90.0))


func _slow(rules: PachinkoRules) -> SlowMotion:
	var slow := SlowMotion.new()
	add_child_autofree(slow)
	slow.bind(rules)
	return slow


# Runs the slow motion and the game for `seconds` of real time the way the game does.
func _play(slow: SlowMotion, rules: PachinkoRules, seconds: float) -> PackedFloat32Array:
	var scales := PackedFloat32Array()
	for frame in int(seconds / FRAME):
		var factor := slow.update(rules, FRAME)
		scales.append(factor)
		rules.advance(FRAME * factor)
	return scales


func test_a_ball_falling_into_a_mouth_is_seen_coming() -> void:
	var rules := _rules()
	var approach := PocketApproach.new(rules.level, rules.world.tuning.gravity)
	var mouth := rules.level.pockets[0].position
	var half := rules.level.pockets[0].width * 0.5
	assert_eq(approach.mouth_count(), rules.level.pockets.size())
	assert_true(approach.entering(mouth + Vector2(0, -30), Vector2(0, 60), null), "above, falling")
	assert_true(approach.entering(mouth + Vector2(0, 4), Vector2.ZERO, null), "inside the cup")
	assert_false(
		approach.entering(mouth + Vector2(half * 3.0, -30), Vector2(0, 60), null), "beside it"
	)
	assert_false(approach.entering(mouth + Vector2(0, -30), Vector2(0, -400), null), "rising")
	assert_false(approach.entering(mouth + Vector2(0, -300), Vector2.ZERO, null), "far above")


func test_a_shut_attacker_is_no_mouth() -> void:
	var level: BoardLevel = (load(CLASSIC) as BoardLevel).duplicate_level()
	level.pockets = []
	var at := Vector2(350, 420)
	var attacker := BonusPocketSpec.of_role(BonusPocketSpec.Role.ATTACKER, at, 60.0, 32.0, 15)
	level.bonus_pockets = [attacker]
	var rules := PachinkoRules.new(level, 1)
	var approach := PocketApproach.new(level, rules.world.tuning.gravity)
	assert_false(approach.entering(at + Vector2(0, -20), Vector2(0, 80), rules.bonus), "lid down")
	assert_true(approach.entering(at + Vector2(0, -20), Vector2(0, 80), null), "lid up")


func test_no_slow_motion_while_a_stream_fills_the_field() -> void:
	var rules := _rules()
	var slow := _slow(rules)
	_leave(rules, 1)
	for i in SlowMotion.MAX_IN_PLAY:
		rules.place_ball(Vector2(200.0 + 30.0 * i, 120.0))
	_drop_into_pocket(rules)
	assert_false(SlowMotion.in_last_balls(rules), "too many balls in the field")
	slow.update(rules, FRAME)
	assert_eq(slow.triggers, 0)


func test_no_slow_motion_while_the_player_has_plenty_of_balls() -> void:
	var rules := _rules()
	var slow := _slow(rules)
	_drop_into_pocket(rules)
	var scales := _play(slow, rules, 1.0)
	assert_eq(slow.triggers, 0, "not the last balls")
	for factor in scales:
		assert_eq(factor, 1.0)


func test_the_last_balls_slow_down_and_come_back_after_the_catch() -> void:
	var rules := _rules()
	var slow := _slow(rules)
	var bank := RecordingBank.new()
	add_child_autofree(bank)
	slow.set_sounds(bank)
	watch_signals(slow)
	_leave(rules, 1)
	var ball := _drop_into_pocket(rules)
	var scales := _play(slow, rules, 3.0)
	assert_eq(slow.triggers, 1, "one slow motion")
	assert_signal_emitted_with_parameters(slow, "started", [ball])
	assert_almost_eq(_lowest(scales), SlowMotion.SLOW_SCALE, 0.001, "down to the slowest")
	assert_false(rules.world.has_ball(ball), "the ball went in")
	assert_eq(scales[scales.size() - 1], 1.0, "full speed again")
	assert_false(slow.is_slow())
	assert_signal_emitted(slow, "ended")
	assert_eq(bank.heard, [SoundBank.SLOW_MO] as Array[StringName], "its sound was asked for")
	var slow_frames := 0
	for factor in scales:
		slow_frames += 1 if factor < 1.0 else 0
	var longest := SlowMotion.MAX_HOLD + SlowMotion.EASE_OUT
	assert_lt(slow_frames * FRAME, longest + FRAME, "never longer than the longest hold")


func test_slow_motion_ends_after_its_longest_hold_even_if_the_ball_never_lands() -> void:
	var rules := _rules()
	var slow := _slow(rules)
	_leave(rules, 2)
	_drop_into_pocket(rules)
	# The game clock stands still (paused world): the ball stays "about to enter".
	var scales := PackedFloat32Array()
	for frame in int(3.0 / FRAME):
		scales.append(slow.update(rules, FRAME))
	assert_eq(slow.triggers, 1)
	var slow_frames := 0
	for factor in scales:
		slow_frames += 1 if factor < 1.0 else 0
	var longest := SlowMotion.MAX_HOLD + SlowMotion.EASE_OUT
	assert_almost_eq(slow_frames * FRAME, longest, FRAME * 2.0, "held at most MAX_HOLD")
	assert_eq(scales[scales.size() - 1], 1.0, "back to full speed")
	assert_eq(slow.triggers, 1, "and the same ball never slows the game twice")


func test_game_over_and_a_new_game_put_the_clock_back_at_once() -> void:
	var rules := _rules()
	var slow := _slow(rules)
	_leave(rules, 1)
	_drop_into_pocket(rules)
	slow.update(rules, FRAME)
	slow.update(rules, FRAME)
	assert_true(slow.is_slow())
	rules.state = PachinkoRules.State.GAME_OVER
	assert_eq(slow.update(rules, FRAME), 1.0, "game over: full speed")
	assert_false(slow.is_slow())
	rules.state = PachinkoRules.State.PLAYING
	slow.update(rules, FRAME)
	slow.bind(_rules())
	assert_eq(slow.time_scale(), 1.0, "a new game starts at full speed")


func test_a_game_played_through_slow_motion_keeps_its_state_hash() -> void:
	# The scene with its juice on, frames of 1/60 s scaled by the slow motion, against bare
	# rules of the same seed given the same inputs and the step counts the scene's frames ran.
	var game := (load(GAME) as PackedScene).instantiate() as PachinkoGame
	add_child_autofree(game)
	var rules := game.rules
	var steps := PackedInt32Array()
	var slowed := 0
	_scripted_start(rules)
	for frame in 900:
		_scripted_input(rules, frame)
		var factor := game.juice().time_scale(rules, FRAME)
		slowed += 1 if factor < 1.0 else 0
		steps.append(rules.advance(FRAME * factor))
	assert_gt(slowed, 0, "the last balls went slow at least once")
	var recorder := game.recorder()
	var bare := PachinkoRules.new(rules.level, recorder.finish().rng_seed)
	_scripted_start(bare)
	for frame in steps.size():
		_scripted_input(bare, frame)
		bare.run_steps(steps[frame])
	assert_eq(bare.world.state_hash(), rules.world.state_hash(), "the same game")
	assert_eq(bare.stats(), rules.stats(), "the same counts")


# Two balls to shoot and one dropped into a pocket: the last balls from the start.
func _scripted_start(rules: PachinkoRules) -> void:
	rules.start_game()
	_leave(rules, 2)
	_drop_into_pocket(rules)


func _scripted_input(rules: PachinkoRules, frame: int) -> void:
	if rules.loaded and frame % 40 == 20:
		rules.fire(20.0 + float(frame % 9) * 10.0)


func _lowest(values: PackedFloat32Array) -> float:
	var lowest := INF
	for value in values:
		lowest = minf(lowest, value)
	return lowest
