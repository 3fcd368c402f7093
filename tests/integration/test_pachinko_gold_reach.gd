extends GutTest
## Gold pins are a choice of power: on every shipped board each gold pin is touched by some
## power (fired through the real rules, one lone ball at a time), and no held strength (a
## handle window, strength ± LaunchHandle.JITTER, as PinReach records it) touches every pin
## of a set.

const BOARDS: Array[String] = ["classic", "tulips", "windmills", "fever", "hanami"]


func _level(id: String) -> BoardLevel:
	var level := BoardLoader.load_board("res://levels/pachinko/%s.board" % id).level
	return level.duplicate(true) as BoardLevel


# Fires one lone ball at `power` on a fresh game and returns the pins it touched.
func _touched(level: BoardLevel, power: float) -> Dictionary:
	var rules := PachinkoRules.new(level, 1)
	rules.start_game()
	var touched := {}
	rules.world.pin_hit.connect(func(_b: int, pin: int, _s: float) -> void: touched[pin] = true)
	rules.fire(power)
	var seconds := 0.0
	while rules.balls_in_play() > 0 and seconds < PinReach.MAX_SECONDS:
		rules.advance(0.1)
		seconds += 0.1
	return touched


func test_every_gold_pin_is_touched_by_some_power() -> void:
	for id in BOARDS:
		var level := _level(id)
		var gold := GoldPins.new(level, 5)
		gold.light_first_set()
		for pin in gold.pins:
			var powers := gold.reach.powers_reaching(pin)
			assert_false(powers.is_empty(), "%s: pin %d is reached by some power" % [id, pin])
			if not powers.is_empty():
				var touched := _touched(level, powers[powers.size() / 2])
				assert_true(touched.has(pin), "%s: the rules' own shot touches pin %d" % [id, pin])


func test_no_held_strength_reaches_a_whole_set() -> void:
	for id in BOARDS:
		var gold := GoldPins.new(_level(id), 11)
		gold.light_first_set()
		for set_index in 6:
			var covering := GoldPinPicker.covering_strengths(gold.reach, gold.pins)
			assert_eq(
				covering.size(), 0, "%s set %d: no one strength reaches all" % [id, set_index]
			)
			for pin in gold.pins.duplicate():
				gold.touch(pin)


func test_a_set_spreads_over_zones() -> void:
	for id in BOARDS:
		var level := _level(id)
		var gold := GoldPins.new(level, 2)
		gold.light_first_set()
		var zones := {}
		for pin in gold.pins:
			zones[GoldPinPicker.zone_of(level, pin)] = true
		assert_gte(zones.size(), 3, "%s: gold pins in three zones or more" % id)
