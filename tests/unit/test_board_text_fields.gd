extends GutTest
## The board reader's field checks, as a designer meets them: each wrong field, item or
## tuning constant is refused with a message naming it, and what is allowed loads.

const PACHINKO := "res://levels/pachinko/classic.board"
const MAZE := "res://levels/maze/classic.board"


# The lines of a shipped board, with the lines holding any of `drop` left out.
func _lines(path: String, drop: Array[String] = []) -> PackedStringArray:
	var kept := PackedStringArray()
	for line in FileAccess.get_file_as_string(path).split("\n"):
		var dropped := false
		for text in drop:
			dropped = dropped or line.contains(text)
		if not dropped and not line.strip_edges().is_empty():
			kept.append(line)
	return kept


func _error(path: String, extra: Array[String], drop: Array[String] = []) -> String:
	var lines := _lines(path, drop)
	lines.append_array(PackedStringArray(extra))
	return str(BoardTextReader.read("\n".join(lines)).get("error", ""))


func _level(path: String, extra: Array[String], drop: Array[String] = []) -> BoardLevel:
	var lines := _lines(path, drop)
	lines.append_array(PackedStringArray(extra))
	return BoardTextReader.read("\n".join(lines)).get("level")


func test_a_pin_naming_a_pocket_the_board_lacks_is_refused_by_pin_and_pocket() -> void:
	var pin := '{"pin": {"id": 900, "x": 300, "y": 120, "pocket": %d}}'
	assert_eq(
		_error(PACHINKO, [pin % 150]), "pin 900 names pocket 150; the board has 5 pockets (0 to 4)"
	)
	assert_eq(
		_error(PACHINKO, [pin % 5]),
		"pin 900 names pocket 5; the board has 5 pockets (0 to 4)",
		"pockets count from 0: 5 is one past the last"
	)
	var pins := 0
	for line in _lines(PACHINKO):
		pins += 1 if line.begins_with('{"pin":') else 0
	var no_id := '{"pin": {"x": 300, "y": 120, "pocket": 7}}'
	assert_eq(
		_error(PACHINKO, [no_id]),
		"pins item %d names pocket 7; the board has 5 pockets (0 to 4)" % (pins + 1),
		"a pin without an id is named by its place in the list"
	)
	assert_eq(
		_error(PACHINKO, [pin % 3], ['{"pocket"']),
		"pin 900 names pocket 3; the board has no pockets"
	)


func test_a_pin_of_an_older_file_naming_a_real_pocket_still_loads() -> void:
	var level := _level(PACHINKO, ['{"pin": {"id": 900, "x": 300, "y": 120, "pocket": 4}}'])
	assert_not_null(level, "pocket 4 of 5 is the last pocket")
	var first := _level(PACHINKO, ['{"pin": {"id": 900, "x": 300, "y": 120, "pocket": 0}}'])
	assert_not_null(first, "pocket 0 is the first")


# How many items of `key` ("pin", "ball_start", ...) the board has: a new one is the next.
func _count(path: String, key: String) -> int:
	var count := 0
	for line in _lines(path):
		count += 1 if line.begins_with('{"%s":' % key) else 0
	return count


func test_the_header_says_what_the_file_is() -> void:
	var head: Array[String] = ['{"format":']
	assert_eq(
		_error(PACHINKO, ['{"format": "other", "format_version": 1}'], head),
		'"format" must be "board-studio-board"; this is not a board file'
	)
	assert_eq(
		_error(PACHINKO, ['{"format_version": 1}'], head),
		'"format" must be "board-studio-board"; this is not a board file',
		"no format at all"
	)
	var newer := _error(PACHINKO, ['{"format": "board-studio-board", "format_version": 2}'], head)
	assert_string_contains(newer, "the file is format version 2")
	assert_string_contains(newer, "newer than this game reads (1): update the game")
	assert_eq(
		_error(PACHINKO, ['{"format": "board-studio-board", "format_version": "2"}'], head),
		'"format_version" must be a number',
		"a version in quotes is no version"
	)
	assert_string_contains(
		_error(PACHINKO, ['{"kind": "chess"}'], ['{"kind":']), '"kind" must be "pachinko" or'
	)
	assert_string_contains(
		_error(PACHINKO, ['{"kind": 5}'], ['{"kind":']), '"kind" must be "pachinko" or'
	)
	assert_not_null(_level(PACHINKO, []), "the shipped header reads")


func test_fields_unknown_missing_and_wrong_are_named() -> void:
	assert_eq(_error(PACHINKO, ['{"colour": 1}']), 'unknown field "colour" for a pachinko board')
	assert_eq(_error(MAZE, ['{"fascia": "fever"}']), 'unknown field "fascia" for a maze board')
	assert_eq(_error(PACHINKO, [], ['{"ring_radius":']), 'the field "ring_radius" is missing')
	assert_eq(
		_error(PACHINKO, ['{"ring_radius": 5}'], ['{"ring_radius":']),
		'"ring_radius" must be between 10 and 2048, got 5'
	)
	assert_eq(
		_error(MAZE, ['{"grid_cols": 2.5}'], ['{"grid_cols":']),
		'"grid_cols" must be a whole number'
	)
	assert_string_contains(
		_error(PACHINKO, ['{"fascia": "disco"}'], ['"fascia"']),
		'"fascia" names no machine this game has ("disco")'
	)
	assert_not_null(_level(PACHINKO, [], ['"fascia"']), "the machine may be left out")
	assert_not_null(_level(MAZE, [], ["medal_times"]), "so may the medal times")
	var neon := _level(PACHINKO, ['{"fascia": "neon"}'], ['"fascia"'])
	assert_eq(neon.fascia if neon != null else "", "neon", "a known machine is taken")
	assert_string_contains(
		_error(MAZE, ['{"medal_times": {"easy": [1, 2]}}'], ["medal_times"]), '"medal_times" '
	)
	var ids := _level(PACHINKO, ['{"next_ids": {"pins": 6000}}'])
	assert_not_null(ids, "next_ids is a field every board may have")
	var tuned := _level(PACHINKO, ['{"tuning": {"restitution": 0.5}}'], ['{"tuning":'])
	assert_eq(tuned.tuning.restitution if tuned != null else -1.0, 0.5, "and so is tuning")


func test_each_list_holds_at_most_its_limit() -> void:
	var starts := _count(MAZE, "ball_start")
	var extra: Array[String] = []
	for i in 64 - starts:
		extra.append('{"ball_start": {"x": %d, "y": 17.5}}' % (40 + i))
	assert_not_null(_level(MAZE, extra), "64 ball starts")
	extra.append('{"ball_start": {"x": 200, "y": 17.5}}')
	assert_eq(_error(MAZE, extra), '"ball_starts" has 65 items; at most 64 are allowed')


func test_a_broken_item_is_named_by_its_list_and_place() -> void:
	var next := _count(PACHINKO, "pin") + 1
	var cases := {
		'{"pin": 5}': "must be an object { ... }",
		'{"pin": {"x": 1, "y": 2, "z": 3}}': 'unknown field "z"',
		'{"pin": {"x": 1}}': 'the field "y" is missing',
		'{"pin": {"x": 1, "y": 20000}}': '"y" must be between -10000 and 10000, got 20000',
		'{"pin": {"x": 1, "y": 2, "special": 3}}': '"special" must be true or false',
		'{"pin": {"x": 1, "y": 2, "id": 0}}': '"id" must be between 1 and',
	}
	for line: String in cases:
		var expected := "pins item %d: %s" % [next, cases[line]]
		assert_string_contains(_error(PACHINKO, [line]), expected, line)
		assert_true(_error(PACHINKO, [line]).begins_with("pins item %d: " % next), line)
	var special := _level(PACHINKO, ['{"pin": {"x": 1, "y": 2, "special": true}}'])
	assert_not_null(special, "a special pin is a pin")


func test_a_windmill_is_driven_or_free_never_both_nor_neither() -> void:
	var path := "res://levels/pachinko/windmills.board"
	var next := _count(path, "windmill") + 1
	var wheel := '{"windmill": {"x": 300, "y": 200, "blades": 4, "length": 20%s}}'
	assert_eq(
		_error(path, [wheel % ', "speed": 90, "friction": 10']),
		(
			(
				'windmills item %d: give "speed" (a driven wheel, degrees a second) or "friction"'
				+ " (a free wheel), not both"
			)
			% next
		)
	)
	assert_eq(
		_error(path, [wheel % ""]),
		(
			(
				'windmills item %d: needs "speed" (a driven wheel, degrees a second) or "friction"'
				+ " (a free wheel)"
			)
			% next
		)
	)
	assert_not_null(_level(path, [wheel % ', "speed": 90']), "driven")
	assert_not_null(_level(path, [wheel % ', "friction": 10']), "free")


func test_the_id_counters_name_lists_of_this_board() -> void:
	assert_eq(_error(PACHINKO, ['{"next_ids": 5}']), '"next_ids" must be an object { ... }')
	assert_eq(
		_error(PACHINKO, ['{"next_ids": {"walls": 5}}']),
		'"next_ids" names "walls", which is not an item list of this board'
	)
	assert_string_contains(
		_error(PACHINKO, ['{"next_ids": {"pins": 0}}']), '"next_ids" "pins" must be between 1'
	)
	var level := _level(PACHINKO, ['{"next_ids": {"pins": 7000, "pockets": 40}}'])
	assert_eq(level.next_ids.get("pins", 0) if level != null else 0, 7000)


func test_tuning_constants_are_checked_by_name_type_and_range() -> void:
	var no_tuning: Array[String] = ['{"tuning":']
	assert_eq(_error(PACHINKO, ['{"tuning": 5}'], no_tuning), '"tuning" must be an object { ... }')
	assert_eq(
		_error(PACHINKO, ['{"tuning": {"wobble": 1}}'], no_tuning), 'unknown tuning field "wobble"'
	)
	assert_eq(
		_error(
			PACHINKO, ['{"tuning": {"gutter_slide_time": 0.5, "drain_slide_time": 0.4}}'], no_tuning
		),
		'tuning "gutter_slide_time" is the old name of "drain_slide_time": give only one of them'
	)
	var old := _level(PACHINKO, ['{"tuning": {"gutter_slide_time": 0.25}}'], no_tuning)
	assert_eq(
		old.tuning.drain_slide_time if old != null else -1.0, 0.25, "the old name still reads"
	)
	assert_eq(
		_error(PACHINKO, ['{"tuning": {"gravity": 5}}'], no_tuning),
		'tuning "gravity" must be a pair of numbers [x, y]'
	)
	assert_eq(
		_error(PACHINKO, ['{"tuning": {"speed_cap": 0.5}}'], no_tuning),
		'tuning "speed_cap" must be a whole number'
	)
	assert_eq(
		_error(PACHINKO, ['{"tuning": {"restitution": "high"}}'], no_tuning),
		'tuning "restitution" must be a number'
	)
	assert_string_contains(
		_error(PACHINKO, ['{"tuning": {"restitution": 5}}'], no_tuning),
		'tuning "restitution" must be between'
	)
	var tuned := _level(
		PACHINKO,
		['{"tuning": {"gravity": [0, 500], "speed_cap": 1, "restitution": 0.3}}'],
		no_tuning
	)
	assert_not_null(tuned, "good constants of each type load")
	if tuned != null:
		assert_eq(tuned.tuning.gravity, Vector2(0, 500))
		assert_eq(tuned.tuning.speed_cap, PhysicsTuning.SpeedCap.PER_AXIS)
		assert_eq(tuned.tuning.restitution, 0.3)
