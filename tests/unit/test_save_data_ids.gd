extends GutTest
## Any board id round-trips through save.cfg: keys that are not plain names are written as
## JSON strings, so `=`, `]`, `;`, quotes, newlines, control characters and any Unicode
## survive a save and a load, in both maze modes and in pachinko.

const PATH := "user://test_save_data_ids.cfg"
var nasty_ids := [
	"classic",
	"a=b",
	"a = b = c",
	"=",
	"]",
	"[meta]",
	"[maze_best_seconds_easy]\nclassic",
	"line\nbreak",
	"carriage\rreturn",
	"tab\there",
	'"quoted"',
	'"',
	"back\\slash",
	'\\"',
	"; a comment?",
	"# also a comment?",
	"semi;colon",
	"  spaced  ",
	"ünïcödé ボード 🎯",
	"start of heading\u0001 escape\u001b",
	"bell\u0007 and del\u007f",
	"version",
	'Object(GDScript, "script/source": "x")',
	"x".repeat(300),
]


func after_each() -> void:
	DirAccess.remove_absolute(PATH)


func test_every_nasty_id_round_trips_in_every_record() -> void:
	var data := SaveData.new()
	assert_eq(data.load_file(PATH), "")
	for index in nasty_ids.size():
		var board_id: String = nasty_ids[index]
		data.record_maze_time(board_id, false, 10.0 + index)
		data.record_maze_time(board_id, true, 100.0 + index)
		data.record_pachinko_balls(board_id, 1000 + index)
	var again := SaveData.new()
	assert_eq(again.load_file(PATH), "", "the written file reads without a problem")
	for index in nasty_ids.size():
		var board_id: String = nasty_ids[index]
		var shown := board_id.c_escape().left(60)
		assert_eq(again.best_maze_time(board_id, false), 10.0 + index, "easy: %s" % shown)
		assert_eq(again.best_maze_time(board_id, true), 100.0 + index, "hard: %s" % shown)
		assert_eq(again.best_pachinko_balls(board_id), 1000 + index, "pachinko: %s" % shown)


func test_the_file_stays_one_record_per_line_and_plain_ids_stay_bare() -> void:
	var data := SaveData.new()
	data.load_file(PATH)
	data.record_maze_time("classic", false, 12.5)
	data.record_maze_time("line\nbreak=1", false, 13.5)
	var text := FileAccess.get_file_as_string(PATH)
	assert_string_contains(text, "\nclassic=12.5\n")
	assert_string_contains(text, '\n"line\\nbreak=1"=13.5\n')
	# The bytes, not a "\u" escape for NUL in this file: Godot's editor parses every script
	# at start and printed "Unicode parsing error ... Unexpected NUL character" for it.
	assert_false(FileAccess.get_file_as_bytes(PATH).has(0), "no raw NUL byte")


func test_the_reader_takes_quoted_keys_and_names_bad_ones() -> void:
	var parsed := IniText.parse('[s]\n"a=b"=1\n"c\\"d" = 2\n"open=3\n"x"y=4\n')
	assert_eq(parsed["sections"], {"s": {"a=b": 1.0, 'c"d': 2.0}})
	assert_eq(parsed["problem_count"], 2)
	assert_string_contains(parsed["problems"][0], "line 4 (a quoted key")
	assert_string_contains(parsed["problems"][1], "line 5 (no = after")
