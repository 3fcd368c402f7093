extends GutTest
## Fine keyboard control (a play trial: "tilting is all-or-nothing: a tap or a hold sends
## every ball to the next wall"). A held key tilts the board a little at a time, so a tap
## moves a resting ball a short way and only a hold sends it down a corridor; the same press
## gives the same tilt at any frame rate. (Trial 8's taps: KeyTilt, test_maze_tap_travel.gd.)

const FRAME := 1.0 / 60.0


# Presses `key` for `seconds` at `fps` through TiltMixer, returning the tilt when it comes up.
func _tilt_after_press(key: Vector2, seconds: float, fps: float) -> Vector2:
	var mixer := TiltMixer.new()
	var frames := roundi(seconds * fps)
	for i in frames:
		mixer.update(1.0 / fps, key, Vector3.ZERO)
	return mixer.tilt


# Plays Garden Path: `key` held `seconds`, then let go for 3 s; returns how far each ball
# moved (px).
func _distances_after_press(key: Vector2, seconds: float) -> PackedFloat32Array:
	var level := BoardLoader.load_board("res://levels/maze/garden.board").level
	var rules := MazeRules.new(level)
	var mixer := TiltMixer.new()
	var before := rules.ball_positions()
	rules.start()
	for i in roundi((seconds + 3.0) / FRAME):
		var held := key if float(i) * FRAME < seconds else Vector2.ZERO
		rules.set_tilt(mixer.update(FRAME, held, Vector3.ZERO))
		rules.advance(FRAME)
	var after := rules.ball_positions()
	var moved := PackedFloat32Array()
	for b in before.size():
		moved.append(before[b].distance_to(after[b]))
	return moved


func test_a_tap_tilts_a_little_and_a_hold_tilts_fully() -> void:
	var tap := _tilt_after_press(Vector2.LEFT, 0.15, 60.0)
	assert_between(absf(tap.x), 1.2, 2.0, "a 0.15 s tap: a lean of under 2 degrees")
	var longer := _tilt_after_press(Vector2.LEFT, 0.4, 60.0)
	assert_between(absf(longer.x), absf(tap.x), 2.2, "0.4 s: still the gentle part")
	var hold := _tilt_after_press(Vector2.LEFT, KeyTilt.KEY_FULL_SECONDS, 60.0)
	assert_almost_eq(hold.x, -TiltInput.MAX_TILT_DEG, 0.01, "0.7 s held: full tilt")


func test_the_same_press_gives_the_same_tilt_at_any_frame_rate() -> void:
	var at_60 := _tilt_after_press(Vector2(1.0, -1.0), 0.2, 60.0)
	for fps: float in [5.0, 20.0, 120.0]:
		var at_fps := _tilt_after_press(Vector2(1.0, -1.0), 0.2, fps)
		assert_almost_eq(at_fps.x, at_60.x, 0.01, "%d FPS" % fps)
		assert_almost_eq(at_fps.y, at_60.y, 0.01, "%d FPS" % fps)


func test_letting_go_eases_back_to_level_at_any_frame_rate() -> void:
	var mixer := TiltMixer.new()
	for i in 60:
		mixer.update(FRAME, Vector2.RIGHT, Vector3.ZERO)
	mixer.update(FRAME, Vector2.ZERO, Vector3.ZERO)
	assert_between(mixer.tilt.x, 1.0, 9.0, "one frame after letting go it still leans: no jolt")
	for fps: float in [10.0, 20.0, 60.0]:
		var eased := TiltMixer.new()
		for i in roundi(fps):
			eased.update(1.0 / fps, Vector2.RIGHT, Vector3.ZERO)
		for i in ceili(KeyTilt.KEY_LEVEL_SECONDS * fps - 0.001):
			eased.update(1.0 / fps, Vector2.ZERO, Vector3.ZERO)
		assert_almost_eq(eased.tilt.x, 0.0, 0.001, "%d FPS: level 0.08 s after letting go" % fps)


func test_a_tap_moves_a_resting_ball_a_short_way() -> void:
	var tapped := _distances_after_press(Vector2.LEFT, 0.15)
	var held := _distances_after_press(Vector2.LEFT, 0.6)
	gut.p("Garden Path, 0.15 s Left tap: balls moved %s px" % [tapped])
	gut.p("Garden Path, 0.6 s Left hold: balls moved %s px" % [held])
	for b in tapped.size():
		assert_lt(tapped[b], 12.0, "ball %d moves a short way on a tap" % b)
	var farthest := 0.0
	for b in held.size():
		farthest = maxf(farthest, held[b])
	assert_gt(farthest, 30.0, "a hold still sends a ball along")
