extends GutTest
## The keys' tilt over time (trial 9): a press leans the board a little for a fixed time, a
## hold rolls it on to full tilt, letting go levels it fast; the same at any frame rate.
## (What the ball does with it: test_maze_tap_travel.gd.)

const FRAME := 1.0 / 60.0


# Holds `key` for `seconds` at `fps` through TiltMixer (a press heard first), returning the
# tilt then.
func _tilt_after_press(key: Vector2, seconds: float, fps: float) -> Vector2:
	var mixer := TiltMixer.new()
	mixer.key_pressed(key)
	for i in roundi(seconds * fps):
		mixer.update(1.0 / fps, key, Vector3.ZERO)
	return mixer.tilt


func test_a_press_leans_a_little_for_a_fixed_time_then_levels() -> void:
	var nudge := KeyTilt.NUDGE * TiltInput.MAX_TILT_DEG
	assert_almost_eq(_tilt_after_press(Vector2.LEFT, 0.1, 60.0).x, -nudge, 0.01, "0.1 s: the nudge")
	var mixer := TiltMixer.new()
	mixer.key_pressed(Vector2.LEFT)
	for i in 12:  # 0.2 s with the key up from the start
		mixer.update(FRAME, Vector2.ZERO, Vector3.ZERO)
	assert_eq(mixer.tilt.x, 0.0, "the nudge is over and the board level")


func test_holding_one_second_reaches_full_tilt() -> void:
	for fps: float in [60.0, 20.0, 10.0]:
		var hold := _tilt_after_press(Vector2.LEFT, 1.0, fps)
		assert_almost_eq(hold.x, -TiltInput.MAX_TILT_DEG, 0.01, "%d FPS: 1 s held" % fps)


# Past the nudge, a held key rolls the board on over several tenths of a second, never a
# jump to full tilt.
func test_a_hold_rises_smoothly() -> void:
	var mixer := TiltMixer.new()
	mixer.key_pressed(Vector2.RIGHT)
	var last := 0.0
	for i in 60:
		mixer.update(FRAME, Vector2.RIGHT, Vector3.ZERO)
		if float(i) * FRAME >= KeyNudge.HOLD_SECONDS:
			assert_lt(absf(mixer.tilt.x - last), 1.0, "frame %d: no jolt" % i)
		last = mixer.tilt.x
	assert_gte(KeyNudge.HOLD_RAMP_SECONDS, 0.3, "from level to full over 0.3 s or more")


func test_the_same_press_gives_the_same_tilt_at_any_frame_rate() -> void:
	for seconds: float in [0.1, 0.4]:
		var at_60 := _tilt_after_press(Vector2(1.0, -1.0), seconds, 60.0)
		for fps: float in [10.0, 20.0, 120.0]:
			var at_fps := _tilt_after_press(Vector2(1.0, -1.0), seconds, fps)
			assert_almost_eq(at_fps.x, at_60.x, 0.01, "%.1f s at %d FPS" % [seconds, fps])
			assert_almost_eq(at_fps.y, at_60.y, 0.01, "%.1f s at %d FPS" % [seconds, fps])


func test_letting_go_levels_within_a_tenth_of_a_second_at_any_frame_rate() -> void:
	for fps: float in [10.0, 20.0, 60.0]:
		var mixer := TiltMixer.new()
		mixer.key_pressed(Vector2.RIGHT)
		for i in roundi(fps):
			mixer.update(1.0 / fps, Vector2.RIGHT, Vector3.ZERO)
		mixer.update(1.0 / fps, Vector2.ZERO, Vector3.ZERO)
		if fps >= 20.0:
			assert_gt(mixer.tilt.x, 0.5, "%d FPS: one frame after letting go it still leans" % fps)
		for i in roundi(0.1 * fps) - 1:
			mixer.update(1.0 / fps, Vector2.ZERO, Vector3.ZERO)
		assert_eq(mixer.tilt.x, 0.0, "%d FPS: level 0.1 s after letting go" % fps)


func test_the_fine_key_halves_the_hold_eased_in() -> void:
	var mixer := TiltMixer.new()
	mixer.key_pressed(Vector2.RIGHT)
	for i in 60:
		mixer.update(FRAME, Vector2.RIGHT, Vector3.ZERO, true)
	assert_almost_eq(mixer.tilt.x, TiltInput.MAX_TILT_DEG * 0.5, 0.01, "held with Shift: half")
	mixer.update(FRAME, Vector2.RIGHT, Vector3.ZERO, false)
	assert_between(mixer.tilt.x, 6.0, 9.0, "Shift let go mid-hold: eases back up, no jolt")
	for i in 12:
		mixer.update(FRAME, Vector2.RIGHT, Vector3.ZERO, false)
	assert_almost_eq(mixer.tilt.x, TiltInput.MAX_TILT_DEG, 0.01, "full tilt again")


func test_a_held_stick_with_no_press_event_still_nudges_and_holds() -> void:
	var mixer := TiltMixer.new()
	for i in 6:
		mixer.update(FRAME, Vector2.DOWN, Vector3.ZERO)
	assert_almost_eq(mixer.tilt.y, KeyTilt.NUDGE * TiltInput.MAX_TILT_DEG, 0.01, "a nudge")
	for i in 60:
		mixer.update(FRAME, Vector2.DOWN, Vector3.ZERO)
	assert_almost_eq(mixer.tilt.y, TiltInput.MAX_TILT_DEG, 0.01, "then full tilt")


# The game hands key presses to the keys' tilt from their events; a stick's moves are not
# presses (each would restart the nudge, and a hold would never build up).
func test_a_key_press_is_heard_from_its_event_and_a_stick_move_is_not() -> void:
	var press := InputEventAction.new()
	press.action = &"tilt_left"
	press.pressed = true
	assert_eq(KeyTilt.pressed_direction(press), Vector2.LEFT)
	var stick := InputEventJoypadMotion.new()
	stick.axis = JOY_AXIS_LEFT_X
	stick.axis_value = 1.0
	assert_eq(KeyTilt.pressed_direction(stick), Vector2.ZERO)
