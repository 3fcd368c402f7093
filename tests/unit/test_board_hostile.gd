extends GutTest
## The hostile corpus (tests/fixtures/hostile_boards/): files an attacker or an accident could
## put in a board folder. Every one is refused quickly with the file and the problem named,
## none runs code, and the one well-formed file (a BOM and CRLF line ends) loads.

const ROOT := "res://tests/fixtures/hostile_boards"
const MARKER := "user://hostile_payload_ran.txt"
## Loading one file may never take longer than this (the issue's limit is 5 s a file).
const MAX_MS := 2000.0


func before_all() -> void:
	DirAccess.remove_absolute(ProjectSettings.globalize_path(MARKER))


func test_every_hostile_file_is_refused_fast_and_named() -> void:
	var lines := BoardCheckCli.check_folder(ROOT, BoardLevel.Kind.PACHINKO)
	assert_gt(lines.size(), 15, "the corpus is there")
	for line in lines:
		var path: String = line["path"]
		var file := path.get_file()
		assert_lt(float(line["load_ms"]), MAX_MS, file + " loads fast")
		if file == "bom_crlf_ok.board":
			assert_true(line["ok"], "%s: %s" % [file, line["error"]])
			continue
		assert_false(line["ok"], file + " is refused")
		assert_string_contains(str(line["error"]), path, file + ": the message names the file")
	assert_false(FileAccess.file_exists(MARKER), "no payload ran")


func test_the_reasons_are_the_real_problems() -> void:
	var reasons := {}
	for line in BoardCheckCli.check_folder(ROOT, BoardLevel.Kind.PACHINKO):
		reasons[str(line["path"]).get_file()] = str(line["error"])
	var expected := {
		"coincident_pins.board": "crowd into one",
		"cup_int64.board": "cup_start_balls",
		"deep_nesting.board": "too deep",
		"duplicate_key.board": "given twice",
		"huge_count.board": "at most 5000",
		"inf.board": "finite",
		"nan.board": "NaN and infinity are not JSON numbers",
		"newer_version.board": "newer than this game reads",
		"nul_byte.board": "NUL",
		"binary.board": "NUL",
		"object_raw.board": "Godot values such as Object(...) are not JSON",
		"resource_path.board": "resource_path",
		"restitution_5.board": "restitution",
		"ring_huge.board": "ring_radius",
		"sleep_negative.board": "sleep_time",
		"unknown_field.board": "metadata/payload",
		"system_file_text.board": "line 1 is not valid JSON",
		"repeated_key_escaped.board": 'the key "format_version" is given twice',
		"repeated_key_in_item.board": 'line 19: the key "x" is given twice',
		"repeated_key_in_tuning.board": 'the key "restitution" is given twice',
		"tuning_old_and_new_name.board":
		'"gutter_slide_time" is the old name of "drain_slide_time"',
		"pin_pocket_150.board": "pin 777 names pocket 150; the board has 5 pockets (0 to 4)",
	}
	for file: String in expected:
		assert_string_contains(reasons.get(file, "(missing)"), expected[file], file)
	var system_file: String = reasons["system_file_text.board"]
	assert_false(
		system_file.contains("root"), "the refusal does not quote the file: " + system_file
	)


func test_oversized_mazes_are_refused_by_their_limit() -> void:
	var expected := {
		"crowded_walls.board": "42 walls cross one spot near (192, 18); at most 12 may",
		"flood_boundary_copies.board": "this board's grid takes at most 10448 px",
		"flood_diagonals.board": "The walls are 160727 px long together",
	}
	var lines := BoardCheckCli.check_folder(ROOT, BoardLevel.Kind.MAZE)
	assert_eq(lines.size(), expected.size(), "one line per maze of the corpus")
	for line in lines:
		var file := str(line["path"]).get_file()
		assert_false(line["ok"], file + " is refused")
		assert_string_contains(str(line["error"]), expected.get(file, "(not listed)"), file)
		assert_lt(float(line["load_ms"]), MAX_MS, file + " loads fast")


func test_shipped_boards_all_pass_the_check() -> void:
	for kind: int in [BoardLevel.Kind.PACHINKO, BoardLevel.Kind.MAZE]:
		var lines := BoardCheckCli.check_folder(BoardLoader.LEVELS_DIR, kind)
		var folder := BoardLoader.LEVELS_DIR.path_join(BoardLevel.kind_name(kind))
		var files := Array(DirAccess.get_files_at(folder)).filter(
			func(file: String) -> bool: return file.ends_with(".board")
		)
		assert_eq(lines.size(), files.size(), "one line per shipped board")
		assert_gte(lines.size(), 3)
		for line in lines:
			assert_true(line["ok"], str(line["error"]))


func test_a_missing_player_folder_is_simply_empty() -> void:
	assert_eq(BoardCheckCli.check_folder("user://no_such_boards_folder", 0).size(), 0)
