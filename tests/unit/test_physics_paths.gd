extends GutTest
## Path recording: what a ball passed through between its substeps, for outside checks.


func _world() -> BallWorld:
	var t := TuningPresets.pachinko()
	t.gravity = Vector2.ZERO
	t.max_speed = 10000.0
	var w := BallWorld.new(t)
	w.shapes.add_pin(Vector2(1000, 1000), 1.5)
	return w


func test_nothing_is_recorded_unless_asked() -> void:
	var w := _world()
	w.spawn_ball(Vector2(0, 0), Vector2(3000, 0), 5.0)
	w.step(1.0 / 60.0)
	var paths := w.take_step_paths()
	assert_eq((paths["points"] as PackedVector2Array).size(), 0)


func test_a_fast_ball_reports_each_substep_on_its_line() -> void:
	var w := _world()
	w.spawn_ball(Vector2(0, 0), Vector2(3000, 0), 5.0)
	w.spawn_ball(Vector2(0, 100), Vector2(3000, 0), 5.0)
	w.set_path_recording(true)
	w.step(1.0 / 60.0)
	var paths := w.take_step_paths()
	var slots: PackedInt32Array = paths["slots"]
	var points: PackedVector2Array = paths["points"]
	assert_gt(points.size(), 10, "50 px in one step takes many substeps")
	var last_x := 0.0
	for k: int in points.size():
		if slots[k] == 0:
			assert_almost_eq(points[k].y, 0.0, 1e-3)
			assert_gt(points[k].x, last_x, "in time order")
			last_x = points[k].x
	assert_lt(last_x, w.get_positions()[0].x, "the end position is not repeated")
	assert_eq(slots[0], 0, "grouped by ball, in slot order")
	assert_eq(slots[slots.size() - 1], 1)
	assert_eq((w.take_step_paths()["points"] as PackedVector2Array).size(), 0, "taking clears")
