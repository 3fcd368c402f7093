extends GutTest
## The jackpot's juice and the lights: a jackpot nudges the board and brings it back to
## rest, sweeps a band of light across the field that flashes the pins it crosses, and
## screen shake off keeps the board still; pins light in the colour of what hit them and a
## pocket's rim lights on a catch; every effect asks for its sound.

const CLASSIC := "res://levels/pachinko/classic.board"
const GAME := "res://scenes/pachinko/pachinko_game.tscn"
const FRAME := 1.0 / 60.0
const ATTACKER := Vector2(350, 560)

var _shake_before := true


class RecordingBank:
	extends SoundBank
	var heard: Array[StringName] = []

	func play(sound: StringName, _volume_db: float = 0.0, _pitch: float = 1.0) -> bool:
		heard.append(sound)
		return true


func before_each() -> void:
	_shake_before = App.settings.screen_shake


func after_each() -> void:
	App.settings.screen_shake = _shake_before


func _game() -> PachinkoGame:
	var game := (load(GAME) as PackedScene).instantiate() as PachinkoGame
	add_child_autofree(game)
	return game


func _jackpot(rules: PachinkoRules) -> void:
	rules.bonus.reels_finished.emit(PackedInt32Array([2, 2, 2]), true)


# Classic with one start pocket whose reels have one symbol (every spin a jackpot) and an
# attacker open 5 s.
func _fever_rules() -> PachinkoRules:
	var level: BoardLevel = (load(CLASSIC) as BoardLevel).duplicate_level()
	var start := BonusPocketSpec.of_role(
		BonusPocketSpec.Role.START, Vector2(350, 300), 24.0, 26.0, 2
	)
	start.symbols = 1
	var attacker := BonusPocketSpec.of_role(BonusPocketSpec.Role.ATTACKER, ATTACKER, 60.0, 32.0, 15)
	attacker.open_seconds = 5.0
	level.bonus_pockets = [start, attacker]
	return PachinkoRules.new(level, 3)


# Feeds the start pocket and runs the bonus clock until the attacker opens.
func _open_attacker(rules: PachinkoRules) -> void:
	rules.bonus.catch(0)
	for tick in 200:
		if rules.bonus.any_attacker_open():
			return
		rules.bonus.advance(0.1)


func test_a_jackpot_nudges_the_board_and_it_comes_back_to_rest() -> void:
	var game := _game()
	var view := game.board_view
	var rest := view.position
	var juice := game.juice()
	_jackpot(game.rules)
	assert_true(juice.nudge.is_moving(), "the nudge began")
	var furthest := 0.0
	for frame in int(CameraNudge.SECONDS / FRAME) + 5:
		juice.nudge._process(FRAME)
		furthest = maxf(furthest, view.position.distance_to(rest))
	assert_gt(furthest, CameraNudge.AMPLITUDE * 0.4, "the board moved")
	assert_lt(furthest, CameraNudge.AMPLITUDE * 1.5, "a nudge, not a throw")
	assert_eq(view.position, rest, "back exactly where it was")
	assert_eq(view.nudge, Vector2.ZERO)
	assert_false(juice.nudge.is_processing(), "asleep at rest")


func test_the_nudge_fades_out_to_nothing_before_it_ends() -> void:
	var last := CameraNudge.offset_at(CameraNudge.SECONDS - FRAME * 0.5, Vector2.DOWN)
	assert_lt(last.length(), 0.2, "no jump at the end")
	assert_eq(CameraNudge.offset_at(CameraNudge.SECONDS, Vector2.DOWN), Vector2.ZERO)


func test_screen_shake_off_keeps_the_board_still_but_the_thump_is_heard() -> void:
	App.settings.set_value("screen_shake", false)
	var game := _game()
	var view := game.board_view
	var rest := view.position
	var juice := game.juice()
	_jackpot(game.rules)
	for frame in 20:
		juice.nudge._process(FRAME)
		assert_eq(view.position, rest, "no shake")
	assert_false(juice.nudge.is_moving())
	assert_true(juice.sweep.is_sweeping(), "the light still sweeps")


func test_a_jackpot_sweeps_light_across_the_pins() -> void:
	var game := _game()
	var juice := game.juice()
	var lights := game.board_view.pin_lights()
	_jackpot(game.rules)
	assert_true(juice.sweep.is_sweeping())
	var before := juice.sweep.band_reach()
	for frame in int(LightSweep.SECONDS * 0.5 / FRAME):
		juice.sweep._process(FRAME)
	assert_gt(juice.sweep.band_reach(), before, "the band moves")
	var swept := 0
	# trial 6: every swept pin drew the full halo, a column of big white discs on Hanami
	var pin_sized := 2.0 * maxf(game.rules.level.pin_radius + 0.8, 2.2)
	var widest := 0.0
	for pin in lights.pin_count():
		if lights.glow_of(pin) > 0.0 and lights.tint_of(pin) == LightSweep.PIN_TINT:
			swept += 1
			widest = maxf(widest, lights.flash_reach_of(pin))
	assert_gt(widest, 0.0)
	assert_lte(widest, pin_sized, "the sweep's flash stays pin-sized")
	assert_gt(swept, lights.pin_count() / 5, "pins behind the band flashed")
	for frame in int(LightSweep.SECONDS / FRAME) + 2:
		juice.sweep._process(FRAME)
	assert_false(juice.sweep.is_sweeping(), "gone after its time")
	assert_false(juice.sweep.is_processing())


func test_pins_glow_in_the_colour_of_what_hit_them() -> void:
	var rules := _fever_rules()
	var lights := PinLights.new()
	add_child_autofree(lights)
	lights.bind(rules)
	rules.world.pin_hit.emit(0, 3, 400.0)
	assert_eq(lights.tint_of(3), PinLights.GLOW, "a ball: warm")
	_open_attacker(rules)
	assert_true(rules.bonus.any_attacker_open())
	rules.world.pin_hit.emit(0, 5, 400.0)
	assert_eq(lights.tint_of(5), PinLights.FEVER_GLOW, "a ball in fever: hot pink")
	lights._process(PinLights.FADE_SECONDS + 0.01)
	assert_eq(lights.glow_of(5), 0.0, "and it fades")


func test_a_catch_lights_its_pockets_rim_in_its_colour() -> void:
	var rules := _fever_rules()
	var lights := PinLights.new()
	add_child_autofree(lights)
	lights.bind(rules)
	var catches := CatchLights.new()
	add_child_autofree(catches)
	catches.bind(rules, lights)
	var level := rules.level
	rules.ball_won.emit(1, 0, 7, level.pockets[0].position)
	var rim := 0
	for pin in level.pins.size():
		if level.pin_pocket[pin] == 0:
			rim += 1
			assert_eq(lights.glow_of(pin), 1.0, "rim pin %d lit" % pin)
			assert_eq(lights.tint_of(pin), CatchLights.POCKET)
	assert_gt(rim, 3, "a pocket has a rim")
	var attacker_id := BonusGeometry.pocket_id(level, 1)
	rules.ball_won.emit(2, attacker_id, 15, ATTACKER)
	var last := lights.pin_count() - 1
	assert_eq(lights.glow_of(last), 1.0, "the attacker's catching pin, last of the world's")
	assert_eq(lights.tint_of(last), CatchLights.ROLE_TINTS[BonusPocketSpec.Role.ATTACKER])


func test_the_open_attacker_is_marked_while_fever_lasts() -> void:
	var rules := _fever_rules()
	var beacon := AttackerBeacon.new()
	add_child_autofree(beacon)
	beacon.bind(rules.level, rules.bonus)
	assert_false(beacon.is_pointing())
	_open_attacker(rules)
	assert_true(beacon.is_pointing(), "fever: the attacker is marked")
	assert_true(beacon.is_processing())
	rules.bonus.advance(5.1)
	assert_false(rules.bonus.any_attacker_open())
	beacon._process(FRAME)
	assert_false(beacon.is_pointing())
	assert_false(beacon.is_processing(), "asleep after the round")


func test_every_effect_asks_for_its_sound() -> void:
	var bank := RecordingBank.new()
	add_child_autofree(bank)
	var rules := _fever_rules()
	var nudge := CameraNudge.new()
	add_child_autofree(nudge)
	nudge.attach(null, bank)
	nudge.kick()
	var sweep := LightSweep.new()
	add_child_autofree(sweep)
	sweep.bind(rules.level, null, bank)
	sweep.start()
	var countdown := FeverCountdown.new()
	add_child_autofree(countdown)
	countdown.bind(rules.bonus, rules.level.bonus_pockets.size(), bank)
	_open_attacker(rules)
	for tick in 60:
		rules.bonus.advance(0.1)
		countdown.check()
	assert_eq(countdown.beeps, FeverCountdown.LAST_SECONDS, "one beep for each last second")
	var expected: Array[StringName] = [SoundBank.JACKPOT_THUMP, SoundBank.LIGHT_SWEEP]
	for beep in FeverCountdown.LAST_SECONDS:
		expected.append(SoundBank.FEVER_TICK)
	assert_eq(bank.heard, expected)
	assert_eq(JuiceView.pin_sound(rules.bonus), SoundBank.PIN_TICK, "a plain tick after fever")
	_open_attacker(rules)
	assert_eq(JuiceView.pin_sound(rules.bonus), SoundBank.PIN_FEVER, "a bright one in fever")


func test_the_juice_sounds_are_built() -> void:
	for sound: StringName in [
		SoundBank.SLOW_MO,
		SoundBank.JACKPOT_THUMP,
		SoundBank.LIGHT_SWEEP,
		SoundBank.FEVER_TICK,
		SoundBank.PIN_FEVER
	]:
		var clip := SoundBank.stream(sound)
		assert_not_null(clip, "%s is generated" % sound)
		if clip != null:
			assert_lt(clip.get_length(), 1.5, "%s is short" % sound)
