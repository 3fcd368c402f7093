extends GutTest
## The replay reader's records (tilts, packed tilts, shots): each limit itself is allowed,
## one past it refused by name. The header and the file: test_replay_reader.gd.

const ReplayLines := preload("res://tests/helpers/replay_lines.gd")


func test_tilt_records_are_checked_at_their_limits() -> void:
	var steps_problem := (
		'line 2: "tilt": steps per frame must be 1 to %d' % ReplayReader.MAX_STEPS_PER_FRAME
	)
	assert_eq(ReplayLines.error(ReplayLines.steps(0), [["tilt", 1, 0, 0, 0]]), steps_problem)
	assert_eq(
		ReplayLines.error(
			ReplayLines.steps(9), [["tilt", 1, ReplayReader.MAX_STEPS_PER_FRAME + 1, 0, 0]]
		),
		steps_problem
	)
	var most := ReplayReader.MAX_STEPS_PER_FRAME
	assert_true(ReplayLines.read(ReplayLines.steps(most), [["tilt", 1, most, 0, 0]]).has("replay"))
	var frames_problem := 'line 2: "tilt": the frame count must be 1 to 144000'
	assert_eq(ReplayLines.error(ReplayLines.steps(0), [["tilt", 0, 1, 0, 0]]), frames_problem)
	assert_eq(ReplayLines.error(ReplayLines.steps(0), [["tilt", 144001, 1, 0, 0]]), frames_problem)
	assert_true(
		ReplayLines.read(ReplayLines.steps(144000), [["tilt", 144000, 1, 0, 0]]).has("replay")
	)
	assert_eq(
		ReplayLines.error(ReplayLines.steps(0), [["tilt", 72001, 2, 0, 0]]),
		"line 2: more than 144000 steps in all"
	)
	var tilt_problem := 'line 2: "tilt": a tilt must be within ±1200 hundredths of a degree'
	assert_eq(ReplayLines.error(ReplayLines.steps(1), [["tilt", 1, 1, 1201, 0]]), tilt_problem)
	assert_eq(ReplayLines.error(ReplayLines.steps(1), [["tilt", 1, 1, 0, -1201]]), tilt_problem)
	assert_true(ReplayLines.read(ReplayLines.steps(1), [["tilt", 1, 1, 1200, -1200]]).has("replay"))


func test_records_must_be_named_lists_of_whole_numbers() -> void:
	var shape := 'line 2: a record must be an array that starts with its name, like ["tilt", ...]'
	assert_eq(ReplayLines.error(ReplayLines.steps(0), [{"tilt": 1}]), shape)
	assert_eq(ReplayLines.error(ReplayLines.steps(0), [[]]), shape)
	assert_eq(ReplayLines.error(ReplayLines.steps(0), [[1, 2]]), shape)
	assert_eq(
		ReplayLines.error(ReplayLines.steps(0), [["fire", 0, 1]]),
		'line 2: unknown maze record "fire" (known: tilt, tilts)'
	)
	assert_eq(
		ReplayLines.error(ReplayLines.steps(0), [["tilt", 1, 1, 0]]),
		'line 2: "tilt" takes 4 numbers, got 3'
	)
	assert_eq(
		ReplayLines.error(ReplayLines.steps(0), [["tilt", 1, 1, 0, 0, 0]]),
		'line 2: "tilt" takes 4 numbers, got 5'
	)
	assert_eq(
		ReplayLines.error(ReplayLines.steps(0), [["tilt", 1, 1, 0.5, 0]]),
		'line 2: "tilt": item 3 must be a whole number'
	)
	assert_eq(
		ReplayLines.error(ReplayLines.steps(0), [["tilt", "1", 1, 0, 0]]),
		'line 2: "tilt": item 1 must be a whole number'
	)


func test_a_shots_power_allows_0_to_10000() -> void:
	var problem := 'line 2: "fire": power must be 0 to 10000 hundredths'
	assert_eq(ReplayLines.error(ReplayLines.steps(0, "pachinko"), [["fire", 0, -1]]), problem)
	assert_eq(ReplayLines.error(ReplayLines.steps(0, "pachinko"), [["fire", 0, 10001]]), problem)
	assert_true(
		(
			ReplayLines
			. read(ReplayLines.steps(0, "pachinko"), [["fire", 0, 0], ["fire", 0, 10000]])
			. has("replay")
		)
	)
	var run := 'line 2: "run": steps per frame must be 1 to %d' % ReplayReader.MAX_STEPS_PER_FRAME
	assert_eq(ReplayLines.error(ReplayLines.steps(0, "pachinko"), [["run", 1, 0]]), run)


func test_packed_tilts_read_frame_by_frame() -> void:
	var frames := [2, 100, -100, 1, 0, 1200]
	var read := ReplayLines.read(ReplayLines.steps(3), [["tilts", TiltPacking.encode(frames)]])
	var replay: Replay = read.get("replay")
	assert_not_null(replay, str(read.get("error", "")))
	if replay != null:
		assert_eq(replay.records, [["tilts", 2, 100, -100, 1, 0, 1200]])
	var tilt := TiltPacking.encode([1, 1201, 0])
	assert_eq(
		ReplayLines.error(ReplayLines.steps(1), [["tilts", tilt]]),
		'line 2: "tilts": a tilt must be within ±1200 hundredths of a degree'
	)
	var y_tilt := TiltPacking.encode([1, 0, -1201])
	assert_eq(
		ReplayLines.error(ReplayLines.steps(1), [["tilts", y_tilt]]),
		'line 2: "tilts": a tilt must be within ±1200 hundredths of a degree',
		"the y tilt is checked too"
	)
	var steps_zero := TiltPacking.encode([0, 0, 0])
	assert_eq(
		ReplayLines.error(ReplayLines.steps(0), [["tilts", steps_zero]]),
		'line 2: "tilts": steps per frame must be 1 to 30'
	)
	assert_eq(
		ReplayLines.error(ReplayLines.steps(0), [["tilts", 5]]),
		'line 2: "tilts" takes one text of packed frames, like ["tilts", "CAA"]'
	)
	assert_eq(
		ReplayLines.error(ReplayLines.steps(0), [["tilts", "CAA", "CAA"]]),
		'line 2: "tilts" takes one text of packed frames, like ["tilts", "CAA"]'
	)
	var old := ReplayLines.header("maze", {"replay": 1})
	old.erase("physics")
	old.erase("rules")
	assert_eq(
		ReplayLines.error(old, [["tilts", "CAA"]]),
		'line 2: "tilts" records came with format 2; this file says format 1'
	)


func test_packed_tilts_are_limited_in_length_frames_and_steps() -> void:
	var most := []
	for i in Replay.MAX_PACKED_FRAMES:
		most.append_array([1, 0, 0])
	assert_true(
		ReplayLines.read(ReplayLines.steps(250), [["tilts", TiltPacking.encode(most)]]).has(
			"replay"
		),
		"250 frames"
	)
	most.append_array([1, 0, 0])
	assert_eq(
		ReplayLines.error(ReplayLines.steps(251), [["tilts", TiltPacking.encode(most)]]),
		'line 2: "tilts": more than 250 frames'
	)
	var long := "A".repeat(3001)
	assert_eq(
		ReplayLines.error(ReplayLines.steps(0), [["tilts", long]]),
		'line 2: "tilts": the packed frames are longer than 3000 characters'
	)
	var eight := TiltPacking.encode([8, 0, 0])
	var records := [["tilt", 143999, 1, 0, 0], ["tilts", eight]]
	assert_eq(
		ReplayLines.error(ReplayLines.steps(0), records), "line 3: more than 144000 steps in all"
	)
	var fits := [["tilt", 143992, 1, 0, 0], ["tilts", eight]]
	assert_true(
		ReplayLines.read(ReplayLines.steps(144000), fits).has("replay"), "exactly 144000 steps"
	)


func test_packed_tilts_came_with_format_2() -> void:
	var two := ReplayLines.steps(1)
	two["replay"] = 2
	two.erase("physics")
	two.erase("rules")
	var replay: Replay = ReplayLines.read(two, [["tilts", TiltPacking.encode([1, 5, 5])]]).get(
		"replay"
	)
	assert_not_null(replay, "format 2 has packed tilts")
	var garbage := "*".repeat(3000)
	assert_string_contains(
		ReplayLines.error(ReplayLines.steps(0), [["tilts", garbage]]),
		"not a base64 digit",
		"3000 characters are read"
	)
