extends GutTest
## The replay reader field by field: what a replay file may hold (each limit itself is
## allowed, one past it refused by name), and that a good file becomes the Replay it says.

const Reader := preload("res://scripts/replay/replay_reader.gd")
const TiltPacking := preload("res://scripts/replay/tilt_packing.gd")
## The limits as numbers, not the reader's constants: a changed limit must fail a test.
const MOST_WHOLE := 9_007_199_254_740_991
const MOST_BYTES := 2_097_152
const MOST_LINES := 100_000
const HASH := "0123456789abcdef0123456789abcdef0123456789abcdef0123456789abcdef"


func _header(game: String = "maze", changes: Dictionary = {}) -> Dictionary:
	var header := {
		"replay": Replay.VERSION,
		"game": game,
		"board": "classic",
		"board_hash": HASH,
		"mode": "easy" if game == "maze" else "normal",
		"seed": 7,
		"step_hz": 240,
		"steps": 0,
		"state_hash": 5,
		"seconds": 0.0,
		"physics": 2,
		"rules": 1,
	}
	header.merge(changes, true)
	return header


func _read(header: Dictionary, records: Array = []) -> Dictionary:
	var lines := PackedStringArray([JSON.stringify(header)])
	for record: Variant in records:
		lines.append(JSON.stringify(record))
	return Reader.read("\n".join(lines))


func _error(header: Dictionary, records: Array = []) -> String:
	return str(_read(header, records).get("error", ""))


func _steps(steps: int, game: String = "maze") -> Dictionary:
	return _header(game, {"steps": steps})


func test_a_maze_replay_reads_as_it_was_recorded() -> void:
	var header := _header("maze", {"mode": "hard", "steps": 7, "board_hash": HASH.to_upper()})
	header["seconds"] = 1.5
	var read := _read(header, [["tilt", 2, 3, 100, -200], ["tilt", 1, 1, 0, 0]])
	var replay: Replay = read.get("replay")
	assert_not_null(replay, str(read.get("error", "")))
	if replay == null:
		return
	assert_eq(replay.format_version, Replay.VERSION)
	assert_eq(replay.game, "maze")
	assert_eq(replay.board_id, "classic")
	assert_eq(replay.board_hash, HASH, "the hash is kept in lower case")
	assert_true(replay.hard)
	assert_eq(replay.rng_seed, 7)
	assert_eq(replay.step_hz, 240)
	assert_eq(replay.steps, 7)
	assert_eq(replay.state_hash, 5)
	assert_eq(replay.physics_version, 2)
	assert_eq(replay.rules_version, 1)
	assert_eq(replay.seconds, 1.5)
	assert_eq(replay.records, [["tilt", 2, 3, 100, -200], ["tilt", 1, 1, 0, 0]])


func test_a_pachinko_replay_counts_its_steps_for_each_event() -> void:
	var records := [["run", 3, 2], ["start", 6], ["fire", 6, 10000], ["run", 1, 4], ["fire", 10, 0]]
	var read := _read(_steps(10, "pachinko"), records)
	var replay: Replay = read.get("replay")
	assert_not_null(replay, str(read.get("error", "")))
	if replay == null:
		return
	assert_false(replay.hard)
	assert_eq(replay.records, records)
	var late := [["run", 3, 2], ["fire", 5, 100]]
	assert_eq(
		_error(_steps(6, "pachinko"), late),
		'line 3: "fire" says step 5 but the records before it run 6'
	)
	assert_eq(
		_error(_steps(0, "pachinko"), [["start", 1]]),
		'line 2: "start" says step 1 but the records before it run 0'
	)


func test_the_records_must_add_up_to_the_headers_steps() -> void:
	assert_eq(
		_error(_steps(5), [["tilt", 2, 3, 0, 0]]), "the records run 6 steps but the header says 5"
	)
	assert_eq(
		_error(_steps(7), [["tilt", 2, 3, 0, 0]]), "the records run 6 steps but the header says 7"
	)
	assert_true(_read(_steps(6), [["tilt", 2, 3, 0, 0]]).has("replay"))


func test_the_format_version() -> void:
	assert_eq(
		_error(_header("maze", {"replay": 0})),
		'line 1: "replay" (the format version) must be a whole number from 1'
	)
	assert_eq(
		_error(_header("maze", {"replay": Replay.VERSION + 1})),
		(
			"line 1: format %d is newer than this game reads (%d): update the game"
			% [Replay.VERSION + 1, Replay.VERSION]
		)
	)
	var header := _header()
	header.erase("replay")
	assert_eq(_error(header), 'line 1: the header has no "replay"')
	assert_eq(
		_error(_header("maze", {"replay": 1.5})),
		'line 1: "replay" (the format version) must be a whole number from 1'
	)


func test_older_formats_have_no_physics_or_rules_and_get_version_1() -> void:
	var two := _header()
	two["replay"] = 2
	two.erase("physics")
	two.erase("rules")
	var replay: Replay = _read(two).get("replay")
	assert_not_null(replay, "a format 2 file without physics and rules")
	if replay != null:
		assert_eq(replay.physics_version, 1)
		assert_eq(replay.rules_version, 1)
		assert_eq(replay.format_version, 2)
	var three := _header()
	three["replay"] = 3
	three.erase("rules")
	var read_three: Replay = _read(three).get("replay")
	assert_not_null(read_three, "a format 3 file has physics, no rules")
	if read_three != null:
		assert_eq(read_three.physics_version, 2)
		assert_eq(read_three.rules_version, 1)
	two["physics"] = 1
	assert_eq(_error(two), 'line 1: "physics" came with format 3; this file says format 2')
	three["rules"] = 1
	assert_eq(_error(three), 'line 1: "rules" came with format 4; this file says format 3')
	var four := _header()
	four.erase("rules")
	assert_eq(_error(four), 'line 1: the header has no "rules"')


func test_the_header_fields_and_names() -> void:
	assert_eq(_error(_header("maze", {"script": 1})), 'line 1: unknown header field "script"')
	assert_string_contains(_error(_header("chess")), '"game" must be')
	assert_eq(
		_error(_header("maze", {"board": ""})),
		'line 1: "board" must be a board id of 1 to 64 characters'
	)
	assert_eq(
		_error(_header("maze", {"board": 5})),
		'line 1: "board" must be a board id of 1 to 64 characters'
	)
	assert_eq(
		_error(_header("maze", {"board": "b".repeat(65)})),
		'line 1: "board" must be a board id of 1 to 64 characters'
	)
	assert_true(_read(_header("maze", {"board": "b".repeat(64)})).has("replay"), "64 characters")
	assert_true(_read(_header("maze", {"board": "my board"})).has("replay"), "a space is fine")
	assert_eq(
		_error(_header("maze", {"board": "a\u001fb"})),
		'line 1: "board" contains a control character'
	)
	var hash_problem := 'line 1: "board_hash" must be 64 hexadecimal digits (a SHA-256)'
	assert_eq(_error(_header("maze", {"board_hash": HASH.left(63)})), hash_problem)
	assert_eq(_error(_header("maze", {"board_hash": HASH + "0"})), hash_problem)
	assert_eq(_error(_header("maze", {"board_hash": "g".repeat(64)})), hash_problem)
	assert_eq(_error(_header("maze", {"board_hash": 12})), hash_problem)
	assert_eq(
		_error(_header("maze", {"mode": "normal"})),
		'line 1: "mode" of a maze replay must be one of easy, hard'
	)
	assert_eq(
		_error(_header("pachinko", {"mode": "easy"})),
		'line 1: "mode" of a pachinko replay must be one of normal'
	)
	var easy: Replay = _read(_header("maze", {"mode": "easy"})).get("replay")
	assert_false(easy.hard if easy != null else true, "easy is not hard")


func test_each_header_number_allows_its_range_and_no_more() -> void:
	var ranges := {
		"seed": [-MOST_WHOLE, MOST_WHOLE],
		"step_hz": [1, 1000],
		"state_hash": [0, MOST_WHOLE],
		"physics": [1, 1000],
		"rules": [1, 1000],
	}
	for field: String in ranges:
		var low: int = ranges[field][0]
		var high: int = ranges[field][1]
		var problem := 'line 1: "%s" must be a whole number from %d to %d' % [field, low, high]
		assert_true(_read(_header("maze", {field: low})).has("replay"), "%s %d" % [field, low])
		assert_true(_read(_header("maze", {field: high})).has("replay"), "%s %d" % [field, high])
		if absi(low) < 1000000:
			assert_eq(_error(_header("maze", {field: low - 1})), problem)
			assert_eq(_error(_header("maze", {field: high + 1})), problem)
		assert_eq(_error(_header("maze", {field: 2.5})), problem, field + " 2.5")
		assert_eq(_error(_header("maze", {field: "3"})), problem, field + " as text")
	assert_eq(_error(_steps(-1)), 'line 1: "steps" must be a whole number from 0 to 144000')
	assert_eq(_error(_steps(144001)), 'line 1: "steps" must be a whole number from 0 to 144000')
	var whole: Replay = _read(_header("maze", {"seed": 3.0})).get("replay")
	assert_eq(whole.rng_seed if whole != null else -1, 3, "3.0 is the whole number 3")


func test_the_seconds_must_be_a_finite_number_not_below_zero() -> void:
	var problem := 'line 1: "seconds" must be a finite number >= 0'
	assert_eq(_error(_header("maze", {"seconds": -0.5})), problem)
	assert_eq(_error(_header("maze", {"seconds": "1"})), problem)
	var zero: Replay = _read(_header("maze", {"seconds": 0})).get("replay")
	assert_eq(zero.seconds if zero != null else -1.0, 0.0)
	var whole: Replay = _read(_header("maze", {"seconds": 12})).get("replay")
	assert_eq(whole.seconds if whole != null else -1.0, 12.0, "a whole number of seconds")


func test_tilt_records_are_checked_at_their_limits() -> void:
	var steps_problem := (
		'line 2: "tilt": steps per frame must be 1 to %d' % Reader.MAX_STEPS_PER_FRAME
	)
	assert_eq(_error(_steps(0), [["tilt", 1, 0, 0, 0]]), steps_problem)
	assert_eq(_error(_steps(9), [["tilt", 1, Reader.MAX_STEPS_PER_FRAME + 1, 0, 0]]), steps_problem)
	var most := Reader.MAX_STEPS_PER_FRAME
	assert_true(_read(_steps(most), [["tilt", 1, most, 0, 0]]).has("replay"))
	var frames_problem := 'line 2: "tilt": the frame count must be 1 to 144000'
	assert_eq(_error(_steps(0), [["tilt", 0, 1, 0, 0]]), frames_problem)
	assert_eq(_error(_steps(0), [["tilt", 144001, 1, 0, 0]]), frames_problem)
	assert_true(_read(_steps(144000), [["tilt", 144000, 1, 0, 0]]).has("replay"))
	assert_eq(
		_error(_steps(0), [["tilt", 72001, 2, 0, 0]]), "line 2: more than 144000 steps in all"
	)
	var tilt_problem := 'line 2: "tilt": a tilt must be within ±1200 hundredths of a degree'
	assert_eq(_error(_steps(1), [["tilt", 1, 1, 1201, 0]]), tilt_problem)
	assert_eq(_error(_steps(1), [["tilt", 1, 1, 0, -1201]]), tilt_problem)
	assert_true(_read(_steps(1), [["tilt", 1, 1, 1200, -1200]]).has("replay"))


func test_records_must_be_named_lists_of_whole_numbers() -> void:
	var shape := 'line 2: a record must be an array that starts with its name, like ["tilt", ...]'
	assert_eq(_error(_steps(0), [{"tilt": 1}]), shape)
	assert_eq(_error(_steps(0), [[]]), shape)
	assert_eq(_error(_steps(0), [[1, 2]]), shape)
	assert_eq(
		_error(_steps(0), [["fire", 0, 1]]),
		'line 2: unknown maze record "fire" (known: tilt, tilts)'
	)
	assert_eq(_error(_steps(0), [["tilt", 1, 1, 0]]), 'line 2: "tilt" takes 4 numbers, got 3')
	assert_eq(_error(_steps(0), [["tilt", 1, 1, 0, 0, 0]]), 'line 2: "tilt" takes 4 numbers, got 5')
	assert_eq(
		_error(_steps(0), [["tilt", 1, 1, 0.5, 0]]), 'line 2: "tilt": item 3 must be a whole number'
	)
	assert_eq(
		_error(_steps(0), [["tilt", "1", 1, 0, 0]]), 'line 2: "tilt": item 1 must be a whole number'
	)


func test_a_shots_power_allows_0_to_10000() -> void:
	var problem := 'line 2: "fire": power must be 0 to 10000 hundredths'
	assert_eq(_error(_steps(0, "pachinko"), [["fire", 0, -1]]), problem)
	assert_eq(_error(_steps(0, "pachinko"), [["fire", 0, 10001]]), problem)
	assert_true(_read(_steps(0, "pachinko"), [["fire", 0, 0], ["fire", 0, 10000]]).has("replay"))
	var run := 'line 2: "run": steps per frame must be 1 to %d' % Reader.MAX_STEPS_PER_FRAME
	assert_eq(_error(_steps(0, "pachinko"), [["run", 1, 0]]), run)


func test_packed_tilts_read_frame_by_frame() -> void:
	var frames := [2, 100, -100, 1, 0, 1200]
	var read := _read(_steps(3), [["tilts", TiltPacking.encode(frames)]])
	var replay: Replay = read.get("replay")
	assert_not_null(replay, str(read.get("error", "")))
	if replay != null:
		assert_eq(replay.records, [["tilts", 2, 100, -100, 1, 0, 1200]])
	var tilt := TiltPacking.encode([1, 1201, 0])
	assert_eq(
		_error(_steps(1), [["tilts", tilt]]),
		'line 2: "tilts": a tilt must be within ±1200 hundredths of a degree'
	)
	var y_tilt := TiltPacking.encode([1, 0, -1201])
	assert_eq(
		_error(_steps(1), [["tilts", y_tilt]]),
		'line 2: "tilts": a tilt must be within ±1200 hundredths of a degree',
		"the y tilt is checked too"
	)
	var steps_zero := TiltPacking.encode([0, 0, 0])
	assert_eq(
		_error(_steps(0), [["tilts", steps_zero]]),
		'line 2: "tilts": steps per frame must be 1 to 8'
	)
	assert_eq(
		_error(_steps(0), [["tilts", 5]]),
		'line 2: "tilts" takes one text of packed frames, like ["tilts", "CAA"]'
	)
	assert_eq(
		_error(_steps(0), [["tilts", "CAA", "CAA"]]),
		'line 2: "tilts" takes one text of packed frames, like ["tilts", "CAA"]'
	)
	var old := _header("maze", {"replay": 1})
	old.erase("physics")
	old.erase("rules")
	assert_eq(
		_error(old, [["tilts", "CAA"]]),
		'line 2: "tilts" records came with format 2; this file says format 1'
	)


func test_packed_tilts_are_limited_in_length_frames_and_steps() -> void:
	var most := []
	for i in Replay.MAX_PACKED_FRAMES:
		most.append_array([1, 0, 0])
	assert_true(
		_read(_steps(250), [["tilts", TiltPacking.encode(most)]]).has("replay"), "250 frames"
	)
	most.append_array([1, 0, 0])
	assert_eq(
		_error(_steps(251), [["tilts", TiltPacking.encode(most)]]),
		'line 2: "tilts": more than 250 frames'
	)
	var long := "A".repeat(3001)
	assert_eq(
		_error(_steps(0), [["tilts", long]]),
		'line 2: "tilts": the packed frames are longer than 3000 characters'
	)
	var eight := TiltPacking.encode([8, 0, 0])
	var records := [["tilt", 143999, 1, 0, 0], ["tilts", eight]]
	assert_eq(_error(_steps(0), records), "line 3: more than 144000 steps in all")
	var fits := [["tilt", 143992, 1, 0, 0], ["tilts", eight]]
	assert_true(_read(_steps(144000), fits).has("replay"), "exactly 144000 steps")


func test_the_file_as_a_whole() -> void:
	assert_eq(Reader.read(""), {"error": "the file is empty"})
	assert_eq(Reader.read("\n  \n"), {"error": "the file is empty"})
	var text := (
		"\uFEFF" + JSON.stringify(_steps(1)) + "\n\n" + JSON.stringify(["tilt", 1, 1, 0, 0]) + "\n"
	)
	assert_true(Reader.read(text).has("replay"), "a BOM and blank lines are fine")
	var bad := JSON.stringify(_steps(1)) + "\n\n[1,"
	assert_string_contains(str(Reader.read(bad).get("error")), "line 3 is not valid JSON")
	assert_eq(
		Reader.read('{"replay": 1, "replay": 2}'),
		{"error": 'line 1: the key "replay" is given twice'}
	)
	assert_eq(
		Reader.read("[1]"), {"error": "line 1: the first line must be the header object { ... }"}
	)
	var big := " ".repeat(MOST_BYTES + 1)
	assert_eq(Reader.read(big), {"error": "the file is larger than 2097152 bytes"})
	assert_eq(Reader.read(" ".repeat(MOST_BYTES)), {"error": "the file is empty"}, "2 MB is fine")
	var many := "\n".repeat(MOST_LINES)
	assert_eq(
		Reader.read(many),
		{"error": "the file has %d lines; at most %d" % [MOST_LINES + 1, MOST_LINES]}
	)
	assert_eq(
		Reader.read("\n".repeat(MOST_LINES - 1)), {"error": "the file is empty"}, "the most lines"
	)


func test_the_largest_whole_numbers_a_double_holds_exactly() -> void:
	var seed_problem := (
		'line 1: "seed" must be a whole number from %d to %d' % [-MOST_WHOLE, MOST_WHOLE]
	)
	assert_eq(_error(_header("maze", {"seed": MOST_WHOLE + 1})), seed_problem)
	assert_eq(_error(_header("maze", {"seed": -MOST_WHOLE - 1})), seed_problem)
	var hash_problem := 'line 1: "state_hash" must be a whole number from 0 to %d' % MOST_WHOLE
	assert_eq(_error(_header("maze", {"state_hash": MOST_WHOLE + 1})), hash_problem)
	var big: Replay = _read(_header("maze", {"seed": -MOST_WHOLE})).get("replay")
	assert_eq(big.rng_seed if big != null else 0, -MOST_WHOLE, "kept exactly")


func test_a_hair_below_zero_seconds_is_refused() -> void:
	assert_eq(
		_error(_header("maze", {"seconds": -0.05})),
		'line 1: "seconds" must be a finite number >= 0'
	)


func test_a_format_1_file_needs_every_field_of_its_day() -> void:
	var old := _header("maze", {"replay": 1})
	old.erase("physics")
	old.erase("rules")
	var replay: Replay = _read(old, []).get("replay")
	assert_eq(replay.format_version if replay != null else 0, 1, "a format 1 file reads")
	old.erase("seed")
	assert_eq(_error(old), 'line 1: the header has no "seed"')


func test_packed_tilts_came_with_format_2() -> void:
	var two := _steps(1)
	two["replay"] = 2
	two.erase("physics")
	two.erase("rules")
	var replay: Replay = _read(two, [["tilts", TiltPacking.encode([1, 5, 5])]]).get("replay")
	assert_not_null(replay, "format 2 has packed tilts")
	var garbage := "*".repeat(3000)
	assert_string_contains(
		_error(_steps(0), [["tilts", garbage]]), "not a base64 digit", "3000 characters are read"
	)


func test_the_rules_version_is_the_files() -> void:
	var replay: Replay = _read(_header("maze", {"rules": 3, "physics": 7})).get("replay")
	assert_not_null(replay)
	if replay != null:
		assert_eq(replay.rules_version, 3)
		assert_eq(replay.physics_version, 7)
