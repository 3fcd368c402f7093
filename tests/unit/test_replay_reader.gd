extends GutTest
## The replay reader's header and the file as a whole: what a replay file may hold (each
## limit itself is allowed, one past it refused by name), and that a good file becomes the
## Replay it says. Its records: test_replay_records.gd.

const ReplayLines := preload("res://tests/helpers/replay_lines.gd")
## The limits as numbers, not the reader's constants: a changed limit must fail a test.
const MOST_WHOLE := 9_007_199_254_740_991
const MOST_BYTES := 2_097_152
const MOST_LINES := 100_000


func test_a_maze_replay_reads_as_it_was_recorded() -> void:
	var header := ReplayLines.header(
		"maze", {"mode": "hard", "steps": 7, "board_hash": ReplayLines.HASH.to_upper()}
	)
	header["seconds"] = 1.5
	var read := ReplayLines.read(header, [["tilt", 2, 3, 100, -200], ["tilt", 1, 1, 0, 0]])
	var replay: Replay = read.get("replay")
	assert_not_null(replay, str(read.get("error", "")))
	if replay == null:
		return
	assert_eq(replay.format_version, Replay.VERSION)
	assert_eq(replay.game, "maze")
	assert_eq(replay.board_id, "classic")
	assert_eq(replay.board_hash, ReplayLines.HASH, "the hash is kept in lower case")
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
	var read := ReplayLines.read(ReplayLines.steps(10, "pachinko"), records)
	var replay: Replay = read.get("replay")
	assert_not_null(replay, str(read.get("error", "")))
	if replay == null:
		return
	assert_false(replay.hard)
	assert_eq(replay.records, records)
	var late := [["run", 3, 2], ["fire", 5, 100]]
	assert_eq(
		ReplayLines.error(ReplayLines.steps(6, "pachinko"), late),
		'line 3: "fire" says step 5 but the records before it run 6'
	)
	assert_eq(
		ReplayLines.error(ReplayLines.steps(0, "pachinko"), [["start", 1]]),
		'line 2: "start" says step 1 but the records before it run 0'
	)


func test_the_records_must_add_up_to_the_headers_steps() -> void:
	assert_eq(
		ReplayLines.error(ReplayLines.steps(5), [["tilt", 2, 3, 0, 0]]),
		"the records run 6 steps but the header says 5"
	)
	assert_eq(
		ReplayLines.error(ReplayLines.steps(7), [["tilt", 2, 3, 0, 0]]),
		"the records run 6 steps but the header says 7"
	)
	assert_true(ReplayLines.read(ReplayLines.steps(6), [["tilt", 2, 3, 0, 0]]).has("replay"))


func test_the_format_version() -> void:
	assert_eq(
		ReplayLines.error(ReplayLines.header("maze", {"replay": 0})),
		'line 1: "replay" (the format version) must be a whole number from 1'
	)
	assert_eq(
		ReplayLines.error(ReplayLines.header("maze", {"replay": Replay.VERSION + 1})),
		(
			"line 1: format %d is newer than this game reads (%d): update the game"
			% [Replay.VERSION + 1, Replay.VERSION]
		)
	)
	var header := ReplayLines.header()
	header.erase("replay")
	assert_eq(ReplayLines.error(header), 'line 1: the header has no "replay"')
	assert_eq(
		ReplayLines.error(ReplayLines.header("maze", {"replay": 1.5})),
		'line 1: "replay" (the format version) must be a whole number from 1'
	)


func test_older_formats_have_no_physics_or_rules_and_get_version_1() -> void:
	var two := ReplayLines.header()
	two["replay"] = 2
	two.erase("physics")
	two.erase("rules")
	var replay: Replay = ReplayLines.read(two).get("replay")
	assert_not_null(replay, "a format 2 file without physics and rules")
	if replay != null:
		assert_eq(replay.physics_version, 1)
		assert_eq(replay.rules_version, 1)
		assert_eq(replay.format_version, 2)
	var three := ReplayLines.header()
	three["replay"] = 3
	three.erase("rules")
	var read_three: Replay = ReplayLines.read(three).get("replay")
	assert_not_null(read_three, "a format 3 file has physics, no rules")
	if read_three != null:
		assert_eq(read_three.physics_version, 2)
		assert_eq(read_three.rules_version, 1)
	two["physics"] = 1
	assert_eq(
		ReplayLines.error(two), 'line 1: "physics" came with format 3; this file says format 2'
	)
	three["rules"] = 1
	assert_eq(
		ReplayLines.error(three), 'line 1: "rules" came with format 4; this file says format 3'
	)
	var four := ReplayLines.header()
	four.erase("rules")
	assert_eq(ReplayLines.error(four), 'line 1: the header has no "rules"')


func test_the_header_fields_and_names() -> void:
	assert_eq(
		ReplayLines.error(ReplayLines.header("maze", {"script": 1})),
		'line 1: unknown header field "script"'
	)
	assert_string_contains(ReplayLines.error(ReplayLines.header("chess")), '"game" must be')
	assert_eq(
		ReplayLines.error(ReplayLines.header("maze", {"board": ""})),
		'line 1: "board" must be a board id of 1 to 64 characters'
	)
	assert_eq(
		ReplayLines.error(ReplayLines.header("maze", {"board": 5})),
		'line 1: "board" must be a board id of 1 to 64 characters'
	)
	assert_eq(
		ReplayLines.error(ReplayLines.header("maze", {"board": "b".repeat(65)})),
		'line 1: "board" must be a board id of 1 to 64 characters'
	)
	assert_true(
		ReplayLines.read(ReplayLines.header("maze", {"board": "b".repeat(64)})).has("replay"),
		"64 characters"
	)
	assert_true(
		ReplayLines.read(ReplayLines.header("maze", {"board": "my board"})).has("replay"),
		"a space is fine"
	)
	assert_eq(
		ReplayLines.error(ReplayLines.header("maze", {"board": "a\u001fb"})),
		'line 1: "board" contains a control character'
	)
	var hash_problem := 'line 1: "board_hash" must be 64 hexadecimal digits (a SHA-256)'
	assert_eq(
		ReplayLines.error(ReplayLines.header("maze", {"board_hash": ReplayLines.HASH.left(63)})),
		hash_problem
	)
	assert_eq(
		ReplayLines.error(ReplayLines.header("maze", {"board_hash": ReplayLines.HASH + "0"})),
		hash_problem
	)
	assert_eq(
		ReplayLines.error(ReplayLines.header("maze", {"board_hash": "g".repeat(64)})), hash_problem
	)
	assert_eq(ReplayLines.error(ReplayLines.header("maze", {"board_hash": 12})), hash_problem)
	assert_eq(
		ReplayLines.error(ReplayLines.header("maze", {"mode": "normal"})),
		'line 1: "mode" of a maze replay must be one of easy, hard'
	)
	assert_eq(
		ReplayLines.error(ReplayLines.header("pachinko", {"mode": "easy"})),
		'line 1: "mode" of a pachinko replay must be one of normal'
	)
	var easy: Replay = ReplayLines.read(ReplayLines.header("maze", {"mode": "easy"})).get("replay")
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
		assert_true(
			ReplayLines.read(ReplayLines.header("maze", {field: low})).has("replay"),
			"%s %d" % [field, low]
		)
		assert_true(
			ReplayLines.read(ReplayLines.header("maze", {field: high})).has("replay"),
			"%s %d" % [field, high]
		)
		if absi(low) < 1000000:
			assert_eq(ReplayLines.error(ReplayLines.header("maze", {field: low - 1})), problem)
			assert_eq(ReplayLines.error(ReplayLines.header("maze", {field: high + 1})), problem)
		assert_eq(
			ReplayLines.error(ReplayLines.header("maze", {field: 2.5})), problem, field + " 2.5"
		)
		assert_eq(
			ReplayLines.error(ReplayLines.header("maze", {field: "3"})), problem, field + " as text"
		)
	assert_eq(
		ReplayLines.error(ReplayLines.steps(-1)),
		'line 1: "steps" must be a whole number from 0 to 144000'
	)
	assert_eq(
		ReplayLines.error(ReplayLines.steps(144001)),
		'line 1: "steps" must be a whole number from 0 to 144000'
	)
	var whole: Replay = ReplayLines.read(ReplayLines.header("maze", {"seed": 3.0})).get("replay")
	assert_eq(whole.rng_seed if whole != null else -1, 3, "3.0 is the whole number 3")


func test_the_seconds_must_be_a_finite_number_not_below_zero() -> void:
	var problem := 'line 1: "seconds" must be a finite number >= 0'
	assert_eq(ReplayLines.error(ReplayLines.header("maze", {"seconds": -0.5})), problem)
	assert_eq(ReplayLines.error(ReplayLines.header("maze", {"seconds": "1"})), problem)
	var zero: Replay = ReplayLines.read(ReplayLines.header("maze", {"seconds": 0})).get("replay")
	assert_eq(zero.seconds if zero != null else -1.0, 0.0)
	var whole: Replay = ReplayLines.read(ReplayLines.header("maze", {"seconds": 12})).get("replay")
	assert_eq(whole.seconds if whole != null else -1.0, 12.0, "a whole number of seconds")


func test_the_file_as_a_whole() -> void:
	assert_eq(ReplayReader.read(""), {"error": "the file is empty"})
	assert_eq(ReplayReader.read("\n  \n"), {"error": "the file is empty"})
	var text := (
		"\uFEFF"
		+ JSON.stringify(ReplayLines.steps(1))
		+ "\n\n"
		+ JSON.stringify(["tilt", 1, 1, 0, 0])
		+ "\n"
	)
	assert_true(ReplayReader.read(text).has("replay"), "a BOM and blank lines are fine")
	var bad := JSON.stringify(ReplayLines.steps(1)) + "\n\n[1,"
	assert_string_contains(str(ReplayReader.read(bad).get("error")), "line 3 is not valid JSON")
	assert_eq(
		ReplayReader.read('{"replay": 1, "replay": 2}'),
		{"error": 'line 1: the key "replay" is given twice'}
	)
	assert_eq(
		ReplayReader.read("[1]"),
		{"error": "line 1: the first line must be the header object { ... }"}
	)
	var big := " ".repeat(MOST_BYTES + 1)
	assert_eq(ReplayReader.read(big), {"error": "the file is larger than 2097152 bytes"})
	assert_eq(
		ReplayReader.read(" ".repeat(MOST_BYTES)), {"error": "the file is empty"}, "2 MB is fine"
	)
	var many := "\n".repeat(MOST_LINES)
	assert_eq(
		ReplayReader.read(many),
		{"error": "the file has %d lines; at most %d" % [MOST_LINES + 1, MOST_LINES]}
	)
	assert_eq(
		ReplayReader.read("\n".repeat(MOST_LINES - 1)),
		{"error": "the file is empty"},
		"the most lines"
	)


func test_the_largest_whole_numbers_a_double_holds_exactly() -> void:
	var seed_problem := (
		'line 1: "seed" must be a whole number from %d to %d' % [-MOST_WHOLE, MOST_WHOLE]
	)
	assert_eq(ReplayLines.error(ReplayLines.header("maze", {"seed": MOST_WHOLE + 1})), seed_problem)
	assert_eq(
		ReplayLines.error(ReplayLines.header("maze", {"seed": -MOST_WHOLE - 1})), seed_problem
	)
	var hash_problem := 'line 1: "state_hash" must be a whole number from 0 to %d' % MOST_WHOLE
	assert_eq(
		ReplayLines.error(ReplayLines.header("maze", {"state_hash": MOST_WHOLE + 1})), hash_problem
	)
	var big: Replay = ReplayLines.read(ReplayLines.header("maze", {"seed": -MOST_WHOLE})).get(
		"replay"
	)
	assert_eq(big.rng_seed if big != null else 0, -MOST_WHOLE, "kept exactly")


func test_a_hair_below_zero_seconds_is_refused() -> void:
	assert_eq(
		ReplayLines.error(ReplayLines.header("maze", {"seconds": -0.05})),
		'line 1: "seconds" must be a finite number >= 0'
	)


func test_a_format_1_file_needs_every_field_of_its_day() -> void:
	var old := ReplayLines.header("maze", {"replay": 1})
	old.erase("physics")
	old.erase("rules")
	var replay: Replay = ReplayLines.read(old, []).get("replay")
	assert_eq(replay.format_version if replay != null else 0, 1, "a format 1 file reads")
	old.erase("seed")
	assert_eq(ReplayLines.error(old), 'line 1: the header has no "seed"')


func test_the_rules_version_is_the_files() -> void:
	var replay: Replay = (
		ReplayLines.read(ReplayLines.header("maze", {"rules": 3, "physics": 7})).get("replay")
	)
	assert_not_null(replay)
	if replay != null:
		assert_eq(replay.rules_version, 3)
		assert_eq(replay.physics_version, 7)
