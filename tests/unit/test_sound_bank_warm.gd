extends GutTest
## The sounds build on a worker while the menu is up, so a board's loading does not wait on
## them (they took 0.2 s of it).


func test_sounds_warmed_in_the_background_are_ready_when_asked_for() -> void:
	var names: Array[StringName] = [SoundBank.FANFARE, SoundBank.GOAL_CHIME]
	SoundBank.warm_in_background(names)
	SoundBank.wait_for_background()
	for sound in names:
		var first := SoundBank.stream(sound)
		assert_not_null(first, "%s built" % sound)
		assert_same(SoundBank.stream(sound), first, "%s built once and kept" % sound)
