extends GutTest
## A ball stops soon once the board levels (trial 10: "balls keep rolling for seconds after
## the board levels; the same double tap moved a ball 18 to 100 px; a ball kept rolling toward
## a hole on a level board with no input"). The maze's felt (MazeTilt.felt_drag) holds a
## rolling ball back while the board is near level, so a second tap finds the first one's
## ball at rest, and a full-speed ball stops within a corridor cell of the key's release.

const MazeTaps := preload("res://tests/helpers/maze_taps.gd")
## Switchbacks' corridor cell (px): a 25 px path and a 10 px wall.
const CELL := 35.0


func test_a_ball_at_full_speed_stops_within_a_cell_once_the_board_levels() -> void:
	var rolled := _rolled_after_release()
	gut.p("rolled after release from full speed: %.1f px" % rolled)
	assert_lt(rolled, CELL, "stops within one corridor cell")


func test_two_quick_taps_travel_about_twice_one_tap() -> void:
	var one := MazeTaps.travel(0.1, 60.0)
	for gap: float in [0.3, 0.6]:
		var two := MazeTaps.travel(0.1, 60.0, [0.0, gap])
		gut.p("one tap %.1f px; two taps %.1f s apart %.1f px" % [one, gap, two])
		assert_lte(two, 2.5 * one, "two taps %.1f s apart: at most 2.5 taps' travel" % gap)


func test_a_resting_ball_on_a_level_board_stays() -> void:
	var w := BallWorld.new(TuningPresets.maze())
	MazeTilt.apply(w, Vector2(0.8, 0.0))  # a hand's tremble on the mouse or the stick
	var id := w.spawn_ball(Vector2.ZERO, Vector2.ZERO, 5.0)
	for _i: int in 240:
		w.step(1.0 / 120.0)
	assert_eq(w.get_ball_position(id), Vector2.ZERO, "the felt holds it")


func test_full_tilt_keeps_its_speed() -> void:
	var w := BallWorld.new(TuningPresets.maze())
	MazeTilt.apply(w, Vector2(TiltInput.MAX_TILT_DEG, 0.0))
	var plain := MazeTilt.friction(Vector2(TiltInput.MAX_TILT_DEG, 0.0), w.tuning.rolling_friction)
	assert_eq(w.rolling_friction, plain, "no felt at full tilt")
	MazeTilt.apply(w, Vector2(6.0, 0.0))
	assert_eq(w.rolling_friction, MazeTilt.friction(Vector2(6.0, 0.0), w.tuning.rolling_friction))


## The table for the commit: one tap, two taps, a 0.4 s hold (Switchbacks' first ball, at
## 60 FPS) and the roll after a full-speed release (px).
func test_level_stop_table() -> void:
	var lines := PackedStringArray()
	lines.append("one tap: %.1f" % MazeTaps.travel(0.1, 60.0))
	for gap: float in [0.3, 0.6, 1.5]:
		lines.append("two taps %.1f s apart: %.1f" % [gap, MazeTaps.travel(0.1, 60.0, [0.0, gap])])
	lines.append("fine tap: %.1f" % MazeTaps.travel(0.1, 60.0, [0.0], true))
	lines.append("0.4 s hold: %.1f" % MazeTaps.travel(0.4, 60.0))
	lines.append("0.7 s hold: %.1f" % MazeTaps.travel(0.7, 60.0))
	lines.append("after a full-speed release: %.1f" % _rolled_after_release())
	gut.p("\n".join(lines))
	pass_test("table printed")


# An open board at full tilt right until the ball is at top speed, then levelled as a key let
# go (KeyTilt.level_toward): how far it rolls from the release (px).
func _rolled_after_release() -> float:
	var w := BallWorld.new(TuningPresets.maze())
	var dt := 1.0 / 120.0
	var tilt := Vector2(TiltInput.MAX_TILT_DEG, 0.0)
	MazeTilt.apply(w, tilt)
	var id := w.spawn_ball(Vector2.ZERO, Vector2.ZERO, 5.0)
	for _i: int in 240:
		w.step(dt)
	assert_almost_eq(w.get_ball_velocity(id).x, w.tuning.max_speed, 0.1, "at top speed")
	var released := w.get_ball_position(id).x
	for _i: int in 600:
		tilt = KeyTilt.level_toward(tilt, dt)
		MazeTilt.apply(w, tilt)
		w.step(dt)
	assert_eq(w.get_ball_velocity(id), Vector2.ZERO, "stopped")
	return w.get_ball_position(id).x - released
