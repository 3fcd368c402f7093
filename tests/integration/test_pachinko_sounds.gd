extends GutTest
## The procedural sound bank: every sound is generated, plays on a real bus, and impacts
## are rate-limited with pitch and volume from their speed.

## The jackpot's moments (the reach's rise, the fanfare) last as long as the moment does.
const LONGEST_MOMENT := 4.0


func test_every_recipe_builds_a_clip() -> void:
	for sound in SoundRecipes.names():
		var clip := SoundBank.stream(sound)
		assert_not_null(clip, "%s is generated" % sound)
		if clip != null:
			assert_gt(clip.data.size(), 200, "%s has samples" % sound)
			var longest := LONGEST_MOMENT if JackpotRecipes.has(sound) else 2.0
			assert_lt(clip.get_length(), longest, "%s is a short effect" % sound)


func test_sounds_play_on_an_existing_bus() -> void:
	var bank := SoundBank.new()
	add_child_autofree(bank)
	assert_true(AudioServer.get_bus_index(SoundBank.bus_name()) >= 0)
	assert_true(bank.play(SoundBank.LAUNCH))
	assert_eq(bank.played_count(), 1)


func test_impacts_are_rate_limited_and_scaled_by_speed() -> void:
	var bank := SoundBank.new()
	add_child_autofree(bank)
	assert_false(bank.play_impact(SoundBank.PIN_TICK, 10.0, 40.0, 700.0, 1000), "too soft")
	assert_true(bank.play_impact(SoundBank.PIN_TICK, 700.0, 40.0, 700.0, 1000))
	assert_false(bank.play_impact(SoundBank.PIN_TICK, 700.0, 40.0, 700.0, 1010), "too soon")
	assert_true(bank.play_impact(SoundBank.PIN_TICK, 100.0, 40.0, 700.0, 1100))
	assert_eq(bank.played_count(), 2)
