extends GutTest
## The hostile replay corpus (tests/fixtures/hostile_replays/): files an attacker or an
## accident could hand to `--replay` or leave in user://replays/. Every one is refused
## quickly with the file and the real problem named, and never plays.

const ROOT := "res://tests/fixtures/hostile_replays"
## Reading one file may never take longer than this.
const MAX_MS := 2000.0
const EXPECTED := {
	"bad_board_hash.replay": "64 hexadecimal digits",
	"bad_mode.replay": '"mode" of a maze replay must be one of easy, hard',
	"control_char_board.replay": "control character",
	"deep_nesting.replay": "not valid JSON",
	"empty.replay": "empty",
	"event_step_lie.replay": '"fire" says step 0 but the records before it run 4',
	"frame_count_0.replay": "frame count must be 1",
	"frame_steps_31.replay": "steps per frame must be 1 to 30",
	"frames_huge.replay": '"steps" must be a whole number',
	"fraction_number.replay": "item 3 must be a whole number",
	"godot_object.replay": "not valid JSON",
	"header_array.replay": "first line must be the header",
	"inf.replay": "item 3 must be a whole number",
	"longer_than_a_game.replay": '"steps" must be a whole number from 0 to 144000',
	"missing_field.replay": 'the header has no "board_hash"',
	"nan.replay": "not valid JSON",
	"newer_version.replay": "newer than this game reads",
	"not_json.replay": "not valid JSON",
	"nul_byte.replay": "NUL",
	"object_board.replay": '"board" must be a board id',
	"power_too_high.replay": "power must be 0 to 10000",
	"repeated_key.replay": 'line 1: the key "mode" is given twice',
	"record_object.replay": "a record must be an array",
	"seconds_negative.replay": '"seconds" must be a finite number',
	"seed_fraction.replay": '"seed" must be a whole number',
	"seed_huge.replay": '"seed" must be a whole number',
	"short_record.replay": '"tilt" takes 4 numbers, got 2',
	"system_file_text.replay": "line 1 is not valid JSON: Expected 'true', 'false', or 'null'",
	"steps_huge.replay": '"steps" must be a whole number',
	"steps_mismatch.replay": "the records run 4 steps but the header says 400",
	"string_number.replay": "item 1 must be a whole number",
	"tilt_out_of_range.replay": "within ±1200 hundredths",
	"tilts_bad_digit.replay": 'hold "*", not a base64 digit',
	"tilts_half_frame.replay": "steps, x and y for each frame",
	"tilts_in_format_1.replay": '"tilts" records came with format 2; this file says format 1',
	"tilts_not_text.replay": '"tilts" takes one text of packed frames',
	"tilts_number_too_long.replay": "a packed number runs past 4 digits",
	"tilts_steps_0.replay": '"tilts": steps per frame must be 1 to 30',
	"tilts_tilt_out_of_range.replay": '"tilts": a tilt must be within ±1200 hundredths',
	"tilts_too_long.replay": "packed frames are longer than 3000 characters",
	"tilts_unfinished_number.replay": "end in the middle of a number",
	"unknown_field.replay": 'unknown header field "script"',
	"unknown_record.replay": 'unknown maze record "teleport"',
	"wrong_game.replay": '"game" must be "pachinko" or "maze"',
	"wrong_game_record.replay": 'unknown maze record "fire"',
}


func test_every_hostile_file_is_refused_fast_with_its_problem_named() -> void:
	var files := DirAccess.get_files_at(ROOT)
	var checked := 0
	for file_name in files:
		if not file_name.ends_with(".replay"):
			continue
		var path := "%s/%s" % [ROOT, file_name]
		var started := Time.get_ticks_usec()
		var read := ReplayStore.read_file(path)
		if file_name == "inf.replay":
			# Godot's number parser warns about 1e999 (it becomes inf): expected here.
			assert_engine_error("Exponent too high")
		var ms := (Time.get_ticks_usec() - started) / 1000.0
		assert_lt(ms, MAX_MS, file_name + " is read fast")
		assert_false(read.has("replay"), file_name + " is refused")
		var error := str(read.get("error", ""))
		assert_string_contains(error, path, file_name + ": the message names the file")
		assert_true(EXPECTED.has(file_name), file_name + " has an expected reason in this test")
		assert_string_contains(error, str(EXPECTED.get(file_name, "?")), file_name)
		assert_false(error.contains("root"), file_name + ": the refusal does not quote the file")
		checked += 1
	assert_eq(checked, EXPECTED.size(), "every file of the corpus was checked")


func test_the_command_exits_2_for_a_hostile_file() -> void:
	assert_eq(ReplayCli.run({"replay": ROOT + "/unknown_field.replay"}), 2)
	assert_eq(ReplayCli.run({"replay": ROOT + "/nan.replay"}), 2)


func test_a_file_too_large_is_refused_before_it_is_read() -> void:
	var path := "user://test_replay_huge.replay"
	var file := FileAccess.open(path, FileAccess.WRITE)
	var line := '["tilt",1,1,0,0]\n'
	file.store_string(line.repeat(ReplayReader.MAX_BYTES / line.length() + 10))
	file.close()
	var error := str(ReplayStore.read_file(path).get("error"))
	assert_string_contains(error, "larger than %d bytes" % ReplayReader.MAX_BYTES)
	DirAccess.remove_absolute(ProjectSettings.globalize_path(path))


func test_too_many_lines_are_refused() -> void:
	var error := str(ReplayReader.read("\n".repeat(ReplayReader.MAX_LINES + 5)).get("error"))
	assert_string_contains(error, "at most %d" % ReplayReader.MAX_LINES)
