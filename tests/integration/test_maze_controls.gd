extends GutTest
## How input becomes tilt: the seed's joystick mapping, smooth keys and stick, and the
## phone accelerometer with its calibration and its fallback to the joystick.

const FLAT := Vector3(0.0, 0.0, -9.8)


func test_joystick_travel_maps_to_the_seeds_full_tilt() -> void:
	assert_eq(TiltInput.tilt_from_joystick(Vector2(15.0, -15.0)), Vector2(12.0, -12.0))
	assert_eq(TiltInput.tilt_from_joystick(Vector2(90.0, -40.0)), Vector2(12.0, -12.0))
	assert_eq(TiltInput.joystick_from_tilt(Vector2(12.0, -12.0)), Vector2(15.0, -15.0))
	for tilt: Vector2 in [Vector2(4.0, -2.0), Vector2(0.3, 9.0), Vector2.ZERO]:
		var back := TiltInput.tilt_from_joystick(TiltInput.joystick_from_tilt(tilt))
		assert_almost_eq(back, tilt, Vector2(0.001, 0.001), "the head shows the tilt %s" % tilt)


# Trial 8: "a 14 px drag rolled the balls all the way across". A hand resting on the mouse
# leaves the board level, and the first part of the travel tilts gently.
func test_the_joystick_has_a_dead_zone_and_a_gentle_centre() -> void:
	assert_eq(TiltInput.tilt_from_joystick(Vector2(1.4, -1.4)), Vector2.ZERO, "dead zone")
	var quarter := TiltInput.tilt_from_joystick(Vector2(3.75, 0.0)).x
	var half := TiltInput.tilt_from_joystick(Vector2(7.5, 0.0)).x
	assert_between(quarter, 0.3, 1.5, "a quarter of the way: about a degree")
	assert_between(half, 2.5, 4.0, "half way: about 3 degrees")
	var last := 0.0
	for px in range(2, 16):
		var tilt := TiltInput.tilt_from_joystick(Vector2(float(px), 0.0)).x
		assert_gt(tilt, last, "%d px tilts more than %d px" % [px, px - 1])
		last = tilt


func test_the_joystick_tilts_at_once() -> void:
	var mixer := TiltMixer.new()
	mixer.joystick_moved(Vector2(15.0, 0.0))
	assert_eq(mixer.tilt, Vector2(12.0, 0.0))
	assert_eq(mixer.source, TiltMixer.Source.JOYSTICK)
	mixer.update(1.0 / 60.0, Vector2.ZERO, Vector3.ZERO)
	assert_eq(mixer.tilt, Vector2(12.0, 0.0), "no keys and no accelerometer: the joystick holds")


func test_keys_and_stick_ease_and_scale_with_sensitivity() -> void:
	var mixer := TiltMixer.new()
	mixer.update(1.0 / 60.0, Vector2(0.0, -1.0), Vector3.ZERO)
	assert_between(mixer.tilt.y, -3.0, -0.1, "one frame moves part of the way")
	for i in 120:
		mixer.update(1.0 / 60.0, Vector2(0.0, -1.0), Vector3.ZERO)
	assert_almost_eq(mixer.tilt.y, -12.0, 0.01)
	for i in 120:
		mixer.update(1.0 / 60.0, Vector2.ZERO, Vector3.ZERO)
	assert_eq(mixer.tilt, Vector2.ZERO, "letting go levels the board")
	mixer.sensitivity = 0.5
	for i in 120:
		mixer.update(1.0 / 60.0, Vector2(1.0, 0.0), Vector3.ZERO)
	assert_almost_eq(mixer.tilt.x, 6.0, 0.01, "half sensitivity, half the tilt")


# A play trial: "with the keyboard the tilt keeps going after you let go". A press leans in
# over a few ticks (trial 9's nudge); letting go levels the board within 0.08 s (9 frames here).
func test_letting_go_of_a_key_levels_the_board_quickly() -> void:
	var mixer := TiltMixer.new()
	for i in 120:
		mixer.update(1.0 / 60.0, Vector2(1.0, 0.0), Vector3.ZERO)
	for i in 9:  # 0.15 s
		mixer.update(1.0 / 60.0, Vector2.ZERO, Vector3.ZERO)
	assert_lt(absf(mixer.tilt.x), 0.01, "level after 9 frames")
	for i in 120:
		mixer.update(1.0 / 60.0, Vector2(1.0, 0.0), Vector3.ZERO)
	mixer.update(1.0 / 60.0, Vector2(-1.0, 0.0), Vector3.ZERO)
	assert_lt(mixer.tilt.x, 11.0, "turning the other way swings back faster than it tilts")
	var fresh := TiltMixer.new()
	fresh.update(1.0 / 60.0, Vector2(1.0, 0.0), Vector3.ZERO)
	var nudge := KeyTilt.NUDGE * TiltInput.MAX_TILT_DEG
	assert_between(fresh.tilt.x, 0.5, nudge - 0.1, "a press leans in over a few ticks, no jolt")


func test_a_device_without_accelerometer_keeps_the_joystick() -> void:
	var mixer := TiltMixer.new()
	mixer.update(1.0 / 60.0, Vector2.ZERO, Vector3.ZERO)
	assert_false(mixer.has_accelerometer())
	assert_eq(mixer.source, TiltMixer.Source.NONE)
	mixer.calibrate()
	assert_eq(mixer.neutral, Vector3.ZERO, "nothing to calibrate")


func test_the_accelerometer_tilts_relative_to_the_calibrated_neutral() -> void:
	var mixer := TiltMixer.new()
	var held := Vector3(0.0, 3.0, -9.3)  # the phone held tipped toward the player
	mixer.update(1.0 / 60.0, Vector2.ZERO, held)
	assert_true(mixer.has_accelerometer())
	assert_eq(mixer.source, TiltMixer.Source.ACCELEROMETER)
	assert_eq(mixer.neutral, held, "the first reading is taken as flat")
	for i in 60:
		mixer.update(1.0 / 60.0, Vector2.ZERO, held)
	assert_almost_eq(mixer.tilt.length(), 0.0, 0.01, "held still at neutral: level")
	var tipped_right := held + Vector3(2.0, 0.0, 0.0)
	for i in 120:
		mixer.update(1.0 / 60.0, Vector2.ZERO, tipped_right)
	assert_gt(mixer.tilt.x, 5.0, "tipping right rolls the balls right")
	mixer.calibrate()
	for i in 120:
		mixer.update(1.0 / 60.0, Vector2.ZERO, tipped_right)
	assert_almost_eq(mixer.tilt.x, 0.0, 0.05, "calibrate makes the current pose flat")


func test_a_broken_reading_never_gives_a_broken_tilt() -> void:
	var tilt := TiltInput.tilt_from_accelerometer(Vector3(INF, NAN, 0.0), FLAT, 1.0)
	assert_true(tilt.is_finite())
	assert_eq(TiltInput.clamp_tilt(Vector2(NAN, INF)), Vector2(0.0, 0.0))


# Bug 4: after the joystick moved by even a pixel, Calibrate could not give control back to
# the accelerometer until a reset.
func test_calibrate_hands_control_back_from_the_joystick_to_the_accelerometer() -> void:
	var mixer := TiltMixer.new()
	var held := Vector3(0.0, 2.0, -9.6)
	mixer.update(1.0 / 60.0, Vector2.ZERO, held)
	assert_eq(mixer.source, TiltMixer.Source.ACCELEROMETER)
	mixer.joystick_moved(Vector2(1.0, 0.0))
	mixer.update(1.0 / 60.0, Vector2.ZERO, held)
	assert_eq(mixer.source, TiltMixer.Source.JOYSTICK, "the joystick took over")
	mixer.calibrate()
	assert_eq(mixer.source, TiltMixer.Source.ACCELEROMETER, "Calibrate gives it back")
	var tipped_right := held + Vector3(2.0, 0.0, 0.0)
	for i in 120:
		mixer.update(1.0 / 60.0, Vector2.ZERO, tipped_right)
	assert_gt(mixer.tilt.x, 5.0, "the phone tilts the board again")


func test_calibrate_from_keys_also_hands_control_back() -> void:
	var mixer := TiltMixer.new()
	var held := Vector3(0.0, 0.0, -9.8)
	mixer.update(1.0 / 60.0, Vector2(1.0, 0.0), held)
	assert_eq(mixer.source, TiltMixer.Source.KEYS)
	mixer.calibrate()
	assert_eq(mixer.source, TiltMixer.Source.ACCELEROMETER)


## Presses the head of `stick` (sized 300 × 300) and moves the pointer `travel` screen px.
func _drag_joystick(stick: MazeJoystick, travel: Vector2) -> Vector2:
	stick.size = Vector2(300.0, 300.0)
	var press := InputEventMouseButton.new()
	press.button_index = MOUSE_BUTTON_LEFT
	press.pressed = true
	press.position = Vector2(150.0, 150.0)
	press.global_position = Vector2(150.0, 150.0)
	stick._gui_input(press)
	var motion := InputEventMouseMotion.new()
	motion.global_position = press.global_position + travel
	stick._input(motion)
	return stick.head_offset


func test_the_joystick_tilts_fully_at_15_screen_pixels_as_in_the_seed() -> void:
	var stick: MazeJoystick = add_child_autofree(MazeJoystick.new())
	stick.ui_scale = 2.0
	var head := _drag_joystick(stick, Vector2(15.0, -15.0))
	assert_eq(TiltInput.tilt_from_joystick(head), Vector2(12.0, -12.0), "full tilt at 15 px")
	stick = add_child_autofree(MazeJoystick.new())
	head = _drag_joystick(stick, Vector2(7.5, 0.0))
	assert_eq(head, Vector2(7.5, 0.0), "half way")
	stick = add_child_autofree(MazeJoystick.new())
	stick.sensitivity = 2.0
	head = _drag_joystick(stick, Vector2(7.5, 0.0))
	assert_eq(TiltInput.tilt_from_joystick(head), Vector2(12.0, 0.0), "sensitivity 2: 7.5 px")


# A play trial let go of the mouse with the joystick pushed over: the board stayed tilted
# until a key was pressed. Letting go springs the head back and levels the board.
func test_letting_go_of_the_joystick_levels_the_board() -> void:
	var stick: MazeJoystick = add_child_autofree(MazeJoystick.new())
	var offsets: Array[Vector2] = []
	stick.moved.connect(func(offset: Vector2) -> void: offsets.append(offset))
	var head := _drag_joystick(stick, Vector2(10.0, 0.0))
	assert_gt(head.x, 0.0, "pushed over")
	var up := InputEventMouseButton.new()
	up.button_index = MOUSE_BUTTON_LEFT
	up.pressed = false
	stick._input(up)
	assert_eq(stick.head_offset, Vector2.ZERO, "the head springs back")
	assert_false(stick.engaged, "and no longer follows the pointer")
	assert_eq(offsets[-1], Vector2.ZERO, "the board is told to level")
