extends GutTest
## Taps a player can trust (trial 9: "a 0.3 s tap moved a ball 60-120 px and once overshot
## 130; Shift held 0.4 s moved 7 px: nothing in between"). A key press is a fixed nudge
## whatever its length up to KeyNudge.HOLD_SECONDS, at any frame rate, even a press shorter
## than a frame; a hold rolls on. Each press goes through the game's own path (MazeTaps), on
## Switchbacks' first ball, which has its corridor's length to roll right.

const MazeTaps := preload("res://tests/helpers/maze_taps.gd")
## Press lengths (seconds) the table measures.
const PRESSES: Array[float] = [0.05, 0.1, 0.2, 0.4, 0.7]
## Switchbacks' corridor cell (px): a 25 px path and a 10 px wall.
const CELL := 35.0


func test_a_short_and_a_longer_press_nudge_alike() -> void:
	var short := MazeTaps.travel(0.05, 60.0)
	var longer := MazeTaps.travel(0.15, 60.0)
	gut.p("0.05 s press: %.1f px; 0.15 s press: %.1f px" % [short, longer])
	assert_gt(short, 1.0, "a short press nudges")
	assert_almost_eq(longer, short, 0.5, "0.15 s nudges as far as 0.05 s")


func test_a_nudge_travels_alike_at_10_20_and_60_fps() -> void:
	for press: float in [0.05, 0.1, 0.2]:
		var at_60 := MazeTaps.travel(press, 60.0)
		for fps: float in [20.0, 10.0]:
			var at_fps := MazeTaps.travel(press, fps)
			assert_almost_eq(at_fps, at_60, 0.5, "%.2f s press at %d FPS" % [press, fps])


func test_a_press_and_release_inside_one_frame_still_nudges() -> void:
	var inside := MazeTaps.travel(0.01, 10.0)  # down and up again within a 0.1 s frame
	var tap := MazeTaps.travel(0.1, 60.0)
	assert_almost_eq(inside, tap, 0.5, "a press no frame saw held nudges as a tap does")


func test_a_tap_rolls_a_resting_ball_a_third_of_a_cell() -> void:
	var tap := MazeTaps.travel(0.1, 60.0)
	assert_between(tap, CELL / 3.0, CELL / 2.0, "one tap: a third to a half of a cell")
	var after_stop := MazeTaps.travel(0.1, 60.0, [0.0, 1.5])
	assert_almost_eq(after_stop, 2.0 * tap, 1.0, "a second tap once it stopped: twice as far")
	var fine := MazeTaps.travel(0.1, 60.0, [0.0], true)
	assert_between(fine, 0.4 * tap, 0.65 * tap, "with the fine key: about half as far")


func test_a_hold_rolls_on_and_a_longer_one_never_travels_less() -> void:
	# 2.5 taps, not 3 (trial 10): the felt cut the tap's coast, so its push grew to keep its
	# travel, while a hold's coast is cut as much and its push is the same
	assert_gt(MazeTaps.travel(0.5, 60.0), 2.5 * MazeTaps.travel(0.1, 60.0), "0.5 s rolls on")
	for fps: float in [60.0, 20.0, 10.0]:
		var last := -1.0
		for i in range(1, 13):
			var press := 0.05 * float(i)
			if press * fps - floorf(press * fps + 0.001) > 0.01:
				continue  # not a whole number of frames at this rate
			var moved := MazeTaps.travel(press, fps)
			assert_gte(moved, last - 0.1, "%d FPS: a %.2f s press" % [fps, press])
			last = moved


func test_a_counter_tap_brakes() -> void:
	var rolled := MazeTaps.travel(0.5, 60.0)
	var braked := _braked(0.5, 0.1)
	gut.p("0.5 s Right: %.1f px; then a Left tap: %.1f px" % [rolled, braked])
	# the felt (trial 10) stops the ball soon after the key's release anyway, so the counter-tap
	# has less of its run left to take than before (0.8 of it then)
	assert_between(braked, 0.0, rolled * 0.95, "the counter-tap takes some of the ball's run")


# Right held `seconds`, then a Left tap of `tap` s at once, at 60 FPS: the travel right (px).
func _braked(seconds: float, tap: float) -> float:
	var rules := MazeRules.new(BoardLoader.load_board(MazeTaps.BOARD).level)
	var mixer := TiltMixer.new()
	var recorder := ReplayRecorder.new()
	recorder.attach_maze(rules)
	var before := rules.ball_positions()[0]
	rules.start()
	mixer.key_pressed(Vector2.RIGHT)
	for i in 240:
		var ends := float(i + 1) / 60.0
		if absf(ends - seconds - 1.0 / 60.0) < 0.001:
			mixer.key_pressed(Vector2.LEFT)
		var keys := Vector2.RIGHT if ends <= seconds + 0.0001 else Vector2.ZERO
		if ends > seconds + 0.0001 and ends <= seconds + tap + 0.0001:
			keys = Vector2.LEFT
		MazeFrameSteps.run(rules, recorder, 1.0 / 60.0, mixer, keys)
	return (rules.ball_positions()[0] - before).x


## The table for the commit: each press's travel at 60, 20 and 10 FPS with steady frames,
## then the least and most over ten presses with frames of uneven length (±30 %), as on a
## busy machine (px).
func test_tap_table() -> void:
	var lines := PackedStringArray(["press s | 60 FPS | 20 FPS | 10 FPS"])
	for press in PRESSES:
		var row := "%.2f" % press
		for fps: float in [60.0, 20.0, 10.0]:
			var low := INF
			var high := -INF
			var rng := RandomNumberGenerator.new()
			rng.seed = 9
			for k in 10:
				var moved := MazeTaps.travel(press, fps, [0.0], false, 0.3, rng)
				low = minf(low, moved)
				high = maxf(high, moved)
			row += " | %.1f (%.1f-%.1f)" % [MazeTaps.travel(press, fps), low, high]
		lines.append(row)
	lines.append("fine 0.1 s: %.1f" % MazeTaps.travel(0.1, 60.0, [0.0], true))
	for gap: float in [0.3, 0.6, 1.5]:
		lines.append("two taps %.1f s apart: %.1f" % [gap, MazeTaps.travel(0.1, 60.0, [0.0, gap])])
	gut.p("\n".join(lines))
	pass_test("table printed")
