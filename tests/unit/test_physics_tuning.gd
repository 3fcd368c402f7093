extends GutTest
## Seed constants converted to px and seconds, the tilt → gravity / friction mapping, the
## speed cap, and friction that only slows.


func test_pachinko_defaults_convert_the_flash_constants() -> void:
	var t := TuningPresets.pachinko()
	assert_almost_eq(t.gravity.y, 777.78, 0.01, "0.7 px/tick² at 30 ms")
	assert_eq(t.gravity.x, 0.0)
	assert_almost_eq(t.restitution, 0.6, 1e-6)
	assert_almost_eq(t.min_horizontal_speed, 16.667, 0.001, "0.5 px/tick")
	assert_gt(t.max_speed, sqrt(5.0 * t.gravity.y * 500.0), "fast enough to loop the rail")


func test_maze_defaults_convert_the_tutorial_constants() -> void:
	var t := TuningPresets.maze()
	assert_almost_eq(t.tilt_gravity, 7812.5, 0.001, "2 px/frame² at 16 ms")
	assert_almost_eq(t.rolling_friction, 78.125, 0.001, "μ = 0.01")
	assert_almost_eq(t.max_speed, 93.75, 0.001, "1.5 px/frame")
	assert_almost_eq(t.wall_restitution, 1.0 / 3.0, 1e-6)
	assert_eq(t.gravity, Vector2.ZERO, "the tilt sets gravity")


func test_tilt_maps_to_gravity_and_friction_per_axis() -> void:
	var g := MazeTilt.gravity(Vector2(12, -6), 7812.5)
	assert_almost_eq(g.x, 7812.5 * sin(deg_to_rad(12.0)), 0.001)
	assert_almost_eq(g.y, -7812.5 * sin(deg_to_rad(6.0)), 0.001)
	var f := MazeTilt.friction(Vector2(12, 0), 78.125)
	assert_almost_eq(f.x, 78.125 * cos(deg_to_rad(12.0)), 0.001)
	assert_almost_eq(f.y, 78.125, 0.001)


func test_slow_never_passes_zero() -> void:
	assert_eq(MazeTilt.slow(5.0, 2.0), 3.0)
	assert_eq(MazeTilt.slow(-5.0, 2.0), -3.0)
	assert_eq(MazeTilt.slow(1.0, 2.0), 0.0)
	assert_eq(MazeTilt.slow(-1.0, 2.0), 0.0)


func test_flat_maze_friction_stops_a_ball_without_reversing_it() -> void:
	var w := BallWorld.new(TuningPresets.maze())
	MazeTilt.apply(w, Vector2.ZERO)
	var id := w.spawn_ball(Vector2.ZERO, Vector2(60, -30), 5.0)
	var prev := w.get_ball_velocity(id)
	for _i: int in 240:
		w.step(1.0 / 120.0)
		var v := w.get_ball_velocity(id)
		assert_true(v.x >= 0.0 and v.x <= prev.x, "x only slows")
		assert_true(v.y <= 0.0 and v.y >= prev.y, "y only slows")
		prev = v
	assert_eq(prev, Vector2.ZERO, "and stops")


func test_maze_at_12_degrees_matches_the_seed_speeds() -> void:
	# Seed, per 16 ms frame at 12°: v += 2·sin12 - 0.02·cos12, capped at 1.5 px/frame.
	var seed_v := 0.0
	var frames := 0
	while seed_v < 1.5:
		seed_v = minf(seed_v + 2.0 * sin(deg_to_rad(12.0)) - 0.02 * cos(deg_to_rad(12.0)), 1.5)
		frames += 1
	var w := BallWorld.new(TuningPresets.maze())
	MazeTilt.apply(w, Vector2(12, 0))
	var id := w.spawn_ball(Vector2.ZERO, Vector2.ZERO, 5.0)
	var steps := 0
	while w.get_ball_velocity(id).x < 93.74 and steps < 1000:
		w.step(1.0 / 120.0)
		steps += 1
	assert_almost_eq(w.get_ball_velocity(id).x, 1.5 / 0.016, 0.01, "same top speed in px/s")
	assert_almost_eq(steps / 120.0, frames * 0.016, 0.02, "reached in about the same time")
	for _i: int in 120:
		w.step(1.0 / 120.0)
	assert_almost_eq(w.get_ball_velocity(id).length(), 93.75, 0.01, "stays capped")


func test_speed_cap_holds_under_gravity() -> void:
	var t := TuningPresets.pachinko()
	t.max_speed = 300.0
	var w := BallWorld.new(t)
	var id := w.spawn_ball(Vector2.ZERO, Vector2.ZERO, 5.0)
	for _i: int in 240:
		w.step(1.0 / 120.0)
	assert_almost_eq(w.get_ball_velocity(id).length(), 300.0, 0.01)


func _open_world(tuning: PhysicsTuning) -> Dictionary:
	var w := BallWorld.new(tuning)
	w.build_grid()
	var id := w.spawn_ball(Vector2(500, 500), Vector2.ZERO, 5.0)
	return {"world": w, "id": id}


func test_per_axis_speed_cap_lets_a_diagonal_roll_faster() -> void:
	var t := TuningPresets.maze()
	t.speed_cap = PhysicsTuning.SpeedCap.PER_AXIS
	var run := _open_world(t)
	var w: BallWorld = run["world"]
	MazeTilt.apply(w, Vector2(12.0, 12.0))
	for _s in 60:
		w.step(1.0 / 120.0)
	var v := w.get_ball_velocity(int(run["id"]))
	assert_almost_eq(v.x, t.max_speed, 1e-3, "each axis reaches the cap")
	assert_almost_eq(v.y, t.max_speed, 1e-3)
	t.speed_cap = PhysicsTuning.SpeedCap.TOTAL
	run = _open_world(t)
	w = run["world"]
	MazeTilt.apply(w, Vector2(12.0, 12.0))
	for _s in 60:
		w.step(1.0 / 120.0)
	assert_almost_eq(w.get_ball_velocity(int(run["id"])).length(), t.max_speed, 1e-3)


func test_the_seed_tuning_holds_x_a_frames_friction_under_y() -> void:
	# The seed caps x before its friction and y after: under a full diagonal tilt x tops out
	# at 1.5 - 2·cos(12°)·0.01 = 1.4804 px a 16 ms frame and y at 1.5.
	var t := TuningPresets.maze_seed()
	var run := _open_world(t)
	var w: BallWorld = run["world"]
	MazeTilt.apply(w, Vector2(12.0, 12.0))
	for _s in 60:
		w.step(1.0 / t.fixed_hz)
	var v: Vector2 = w.get_ball_velocity(int(run["id"])) * 0.016
	assert_almost_eq(v.x, 1.5 - 0.02 * cos(deg_to_rad(12.0)), 1e-4, "x: a frame's friction off")
	assert_almost_eq(v.y, 1.5, 1e-4, "y: the cap")
	# Uphill (pushed against the pull) x keeps the whole cap, as in the seed.
	MazeTilt.apply(w, Vector2(-12.0, 12.0))
	w.set_ball_velocity(int(run["id"]), Vector2(t.max_speed * 2.0, 0.0))
	w.step(1.0 / t.fixed_hz)
	assert_almost_eq(w.get_ball_velocity(int(run["id"])).x, t.max_speed, 1e-3, "uphill: cap")


func test_x_cap_friction_time_is_written_only_when_set() -> void:
	var level: BoardLevel = BoardLoader.load_board("res://levels/maze/garden.board").level
	assert_false(BoardTextWriter.write(level).contains("x_cap_friction_time"), "0 is left out")
	level.tuning.x_cap_friction_time = 0.016
	var text := BoardTextWriter.write(level)
	assert_true(text.contains('"x_cap_friction_time": 0.016'), "set: written")
	var back: BoardLevel = BoardLoader.load_bytes(text.to_utf8_buffer(), "test").level
	assert_almost_eq(back.tuning.x_cap_friction_time, 0.016, 1e-9, "read back")


func test_friction_against_gravity_only_lowers_the_downhill_pull() -> void:
	var dt := 1.0 / 120.0
	for mode: int in [
		PhysicsTuning.FrictionAgainst.VELOCITY, PhysicsTuning.FrictionAgainst.GRAVITY
	]:
		var t := TuningPresets.maze()
		t.friction_against = mode
		var run := _open_world(t)
		var w: BallWorld = run["world"]
		var id: int = run["id"]
		w.set_ball_velocity(id, Vector2(-50.0, 0.0))  # rolling uphill
		w.gravity = Vector2(1000.0, 0.0)
		w.rolling_friction = Vector2(100.0, 100.0)
		w.step(dt)
		# Against the velocity friction helps gravity turn it; against gravity it resists.
		var expected := -50.0 + (1000.0 + (100.0 if mode == 0 else -100.0)) * dt
		assert_almost_eq(w.get_ball_velocity(id).x, expected, 1e-3, "mode %d" % mode)


func test_a_tilt_friction_can_hold_never_rolls_the_ball_uphill() -> void:
	var t := TuningPresets.maze()
	t.friction_against = PhysicsTuning.FrictionAgainst.GRAVITY
	var run := _open_world(t)
	var w: BallWorld = run["world"]
	w.gravity = Vector2(50.0, 0.0)
	w.rolling_friction = Vector2(78.125, 78.125)
	for _s in 30:
		w.step(1.0 / 120.0)
	assert_eq(w.get_ball_position(int(run["id"])), Vector2(500, 500), "friction holds it")


func test_board_files_may_choose_the_seed_options() -> void:
	var classic: BoardLevel = BoardLoader.load_board("res://levels/maze/classic.board").level
	assert_eq(classic.tuning.speed_cap, PhysicsTuning.SpeedCap.PER_AXIS)
	assert_eq(classic.tuning.friction_against, PhysicsTuning.FrictionAgainst.GRAVITY)
	assert_eq(classic.tuning.wall_cap_contact, PhysicsTuning.CapContact.GLANCE)
	var other: BoardLevel = BoardLoader.load_board("res://levels/maze/catacombs.board").level
	assert_eq(other.tuning.speed_cap, PhysicsTuning.SpeedCap.TOTAL, "others keep theirs")
	var fields := BoardRanges.tuning_fields()
	assert_eq(fields["speed_cap"][2], 1.0, "the schema bounds the option to its values")


func test_a_board_file_with_the_old_gutter_slide_time_key_still_reads() -> void:
	var path := "res://levels/pachinko/classic.board"
	var text := FileAccess.get_file_as_string(path)
	var old_text := text.replace('"drain_slide_time"', '"gutter_slide_time"')
	assert_string_contains(old_text, '"gutter_slide_time": ')
	old_text = old_text.replace('"gutter_slide_time": 0.5', '"gutter_slide_time": 2.5')
	var read: Dictionary = BoardTextReader.read(old_text)
	assert_false(read.has("error"), str(read.get("error", "")))
	if read.has("error"):
		return
	var level: BoardLevel = read["level"]
	assert_eq(level.tuning.drain_slide_time, 2.5, "read as drain_slide_time")
	var written: String = BoardTextWriter.write(level)
	assert_string_contains(written, '"drain_slide_time": 2.5')
	assert_false(written.contains("gutter_slide_time"), "written with the new name only")
