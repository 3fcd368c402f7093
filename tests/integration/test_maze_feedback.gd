extends GutTest
## What the maze gives back besides the picture: a rolling sound per ball that follows its
## speed, gamepad / phone buzzes on knocks and drops (off with the Vibration setting), and a
## ball that falls into a hole instead of vanishing.

const GAME := preload("res://scenes/maze/maze_game.tscn")
const TEST_SETTINGS := "user://test_maze_feedback_settings.cfg"
const TEST_SAVE := "user://test_maze_feedback_save.cfg"

var _buzzes: Array = []


func before_all() -> void:
	App.load_player_files(TEST_SETTINGS, TEST_SAVE)


func after_all() -> void:
	App.load_player_files(App.SETTINGS_PATH, App.SAVE_PATH)
	for path in [TEST_SETTINGS, TEST_SAVE]:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(path))


func _record(weak: float, strong: float, seconds: float) -> void:
	_buzzes.append([weak, strong, seconds])


func test_the_rolling_sound_follows_the_speed() -> void:
	assert_eq(MazeBallSounds.loudness(0.0), 0.0, "a resting ball is silent")
	assert_eq(MazeBallSounds.loudness(NAN), 0.0)
	assert_lt(MazeBallSounds.loudness(20.0), MazeBallSounds.loudness(80.0), "faster is louder")
	assert_lt(MazeBallSounds.pitch(20.0), MazeBallSounds.pitch(80.0), "and higher")
	var sounds := MazeBallSounds.new()
	add_child_autofree(sounds)
	sounds.update(PackedVector2Array([Vector2(90.0, 0.0), Vector2.ZERO]), 0.5)
	assert_eq(sounds.audible_count(), 1, "one loop per moving ball")
	var fast := sounds.volume_of(0)
	sounds.update(PackedVector2Array([Vector2(30.0, 0.0), Vector2.ZERO]), 0.5)
	assert_lt(sounds.volume_of(0), fast, "slowing down quietens it")
	sounds.stop_all()
	assert_eq(sounds.audible_count(), 0)


func test_the_rolling_clip_loops_without_a_seam() -> void:
	var clip := SoundBank.stream(SoundRecipes.BALL_ROLL)
	assert_eq(clip.loop_mode, AudioStreamWAV.LOOP_FORWARD)
	var frames := clip.data.size() / 2
	assert_lt(clip.loop_end, frames, "the faded tail is never played")
	var steps := 0.0
	for i in range(1, clip.loop_end):
		steps += absf(clip.data.decode_s16(i * 2) - clip.data.decode_s16((i - 1) * 2))
	var typical := steps / float(clip.loop_end - 1)
	var seam := absf(clip.data.decode_s16(0) - clip.data.decode_s16((clip.loop_end - 1) * 2))
	assert_lt(seam, typical * 4.0, "the loop's end runs on into its start like any sample")


func test_knocks_buzz_by_impact_and_the_setting_turns_it_off() -> void:
	var haptics := MazeHaptics.new()
	haptics.output = _record
	_buzzes.clear()
	assert_false(haptics.knock(10.0, 1000), "too soft to feel")
	assert_true(haptics.knock(40.0, 1000))
	assert_false(haptics.knock(100.0, 1020), "merged with the knock just before")
	assert_true(haptics.knock(100.0, 1200))
	assert_eq(_buzzes.size(), 2)
	assert_gt(_buzzes[1][1], _buzzes[0][1], "a harder knock rumbles harder")
	assert_gt(_buzzes[1][2], _buzzes[0][2], "and longer")
	assert_true(haptics.drop())
	haptics.enabled = false
	assert_false(haptics.knock(100.0, 5000))
	assert_false(haptics.drop())
	assert_eq(_buzzes.size(), 3, "nothing while off")


func test_the_vibration_setting_reaches_the_game_and_is_saved() -> void:
	App.settings.set_value("vibration", false)
	var game: MazeGame = GAME.instantiate()
	add_child_autofree(game)
	var haptics: MazeHaptics = game.haptics
	assert_false(haptics.enabled, "off in the settings: off in the game")
	App.settings.set_value("vibration", true)
	assert_true(haptics.enabled, "switched on while playing")
	App.settings.set_value("vibration", false)
	assert_eq(App.settings.save_file(TEST_SETTINGS), OK)
	var reread := GameSettings.new()
	assert_eq(reread.load_file(TEST_SETTINGS), "")
	assert_false(reread.vibration, "saved and read back")
	App.settings.set_value("vibration", true)


func test_a_ball_in_a_hole_falls_with_a_drop_sound_and_a_buzz() -> void:
	var game: MazeGame = GAME.instantiate()
	add_child_autofree(game)
	var haptics: MazeHaptics = game.haptics
	haptics.output = _record
	_buzzes.clear()
	var rules := game.rules
	rules.set_hard_mode(true)
	game._start()
	game._process(0.0)
	var balls := game.stage().balls()
	var id := rules.world.get_ids()[0]
	rules.world.set_ball_position(id, rules.level.holes[1] + Vector2(-12.0, 0.0))
	rules.world.set_ball_velocity(id, Vector2(60.0, 0.0))
	for i in 30:
		rules.step()
	assert_eq(rules.state, MazeRules.State.LOST)
	assert_eq(_buzzes.size(), 1, "the drop buzzed")
	game._process(0.1)
	assert_eq(balls.falling_count(), 1, "the lost ball is falling, not gone")
	assert_eq(balls.shown_count(), rules.ball_total())
	var before: float = balls.fall_progress()
	for i in 20:
		game._process(0.05)
	assert_gt(balls.fall_progress(), before)
	assert_eq(balls.fall_progress(), 1.0, "all the way down")
	var sounds: SoundBank = null
	for child in game.get_children():
		if child is SoundBank:
			sounds = child
	assert_gt(sounds.played_count(), 1, "the drop and the lost cue played")
	rules.reset()
	game._process(0.0)
	assert_eq(balls.falling_count(), 0, "a reset clears the fallen ball")
	assert_eq(balls.shown_count(), rules.ball_total())
