extends GutTest
## The play-test request between the editor and the game: written and read as JSON data,
## every field checked, stale or bad requests removed with a warning, and a hostile file
## that ConfigFile would run as code never runs.

const SCRATCH := "user://test_playtest_request.json"
const BOARD := "res://levels/maze/draft.board"


## Helpers every test class shares (inner classes cannot call the outer script's functions).
class Files:
	static func write_text(path: String, text: String) -> void:
		var file := FileAccess.open(path, FileAccess.WRITE)
		file.store_string(text)
		file.close()

	static func fresh_request() -> Dictionary:
		var now := int(Time.get_unix_time_from_system())
		return {"format": 1, "board": BOARD, "kind": "maze", "written_at": now}


class TestWriteAndRead:
	extends GutTest

	func after_each() -> void:
		DirAccess.remove_absolute(SCRATCH)

	func test_what_the_editor_writes_the_game_reads() -> void:
		assert_eq(PlaytestRequest.write(BOARD, "maze", SCRATCH), "")
		assert_eq(PlaytestRequest.read(SCRATCH), {"board": BOARD, "kind": "maze", "problem": ""})

	func test_the_file_is_plain_json_with_the_four_fields() -> void:
		PlaytestRequest.write("res://levels/pachinko/tulips.board", "pachinko", SCRATCH)
		var data: Variant = JSON.parse_string(FileAccess.get_file_as_string(SCRATCH))
		assert_true(data is Dictionary)
		var keys: Array = (data as Dictionary).keys()
		keys.sort()
		assert_eq(keys, ["board", "format", "kind", "written_at"])

	func test_the_editor_cannot_write_a_request_the_game_would_refuse() -> void:
		var problem := PlaytestRequest.write("user://boards/mine.tres", "maze", SCRATCH)
		assert_string_contains(problem, "res://levels/maze/<name>.board")
		assert_false(FileAccess.file_exists(SCRATCH))


class TestFieldChecks:
	extends GutTest

	# A change to a fresh request, and a piece of the problem it must give.
	const CASES := [
		[{"board": "res://levels/maze/../../project.godot"}, "the board must be a file"],
		[{"board": "res://levels/maze/sub/x.board"}, "the board must be a file"],
		[{"board": "res://levels/maze/x.tscn"}, "the board must be a file"],
		[{"board": "user://levels/maze/x.board"}, "the board must be a file"],
		[{"board": "res://levels/pachinko/x.board"}, "res://levels/maze/<name>.board"],
		[{"board": 7}, "got 7"],
		[{"kind": "pinball"}, "kind must be"],
		[{"kind": 1}, "kind must be"],
		[{"format": 2}, "format must be 1"],
		[{"written_at": "now"}, "written_at must be a number"],
		[{"extra": true}, "unknown field 'extra'"],
	]

	func test_each_bad_field_is_named() -> void:
		var now := Time.get_unix_time_from_system()
		for case: Array in CASES:
			var request := Files.fresh_request()
			request.merge(case[0], true)
			var problem := PlaytestRequest.check(request, now)
			assert_string_contains(problem, str(case[1]), "for %s" % [case[0]])
		assert_eq(PlaytestRequest.check(Files.fresh_request(), now), "", "the fresh one is fine")

	func test_a_missing_field_is_named() -> void:
		var request := Files.fresh_request()
		request.erase("kind")
		assert_string_contains(PlaytestRequest.check(request, 0.0), "'kind' is missing")

	func test_age_limits() -> void:
		var request := Files.fresh_request()
		var written := float(request["written_at"])
		assert_eq(PlaytestRequest.check(request, written + 299.0), "")
		assert_string_contains(PlaytestRequest.check(request, written + 300.0), "old")
		assert_string_contains(PlaytestRequest.check(request, written - 60.0), "future")


class TestTake:
	extends GutTest

	func after_each() -> void:
		DirAccess.remove_absolute(SCRATCH)

	func test_taken_once_by_its_game() -> void:
		PlaytestRequest.write(BOARD, "maze", SCRATCH)
		assert_eq(PlaytestRequest.take("pachinko", SCRATCH), "", "not for pachinko")
		assert_true(FileAccess.file_exists(SCRATCH), "left for the maze")
		assert_eq(PlaytestRequest.take("maze", SCRATCH), BOARD)
		assert_false(FileAccess.file_exists(SCRATCH), "used up")

	func test_stale_request_is_removed_with_a_warning() -> void:
		var request := Files.fresh_request()
		request["written_at"] = float(request["written_at"]) - 3600.0
		Files.write_text(SCRATCH, JSON.stringify(request))
		assert_eq(PlaytestRequest.take("maze", SCRATCH), "")
		assert_false(FileAccess.file_exists(SCRATCH))
		assert_push_warning("stale")

	func test_bad_request_is_removed_with_a_warning_even_for_the_other_game() -> void:
		var request := Files.fresh_request()
		request["board"] = "res://levels/maze/../secret.board"
		Files.write_text(SCRATCH, JSON.stringify(request))
		assert_eq(PlaytestRequest.take("pachinko", SCRATCH), "")
		assert_false(FileAccess.file_exists(SCRATCH))
		assert_push_warning("the board must be a file")

	func test_oversized_file_is_refused_unparsed() -> void:
		Files.write_text(SCRATCH, " ".repeat(PlaytestRequest.MAX_BYTES + 1))
		assert_string_contains(PlaytestRequest.read(SCRATCH)["problem"], "larger than")

	func test_json_that_is_not_an_object_is_refused() -> void:
		Files.write_text(SCRATCH, "[1, 2]")
		assert_string_contains(PlaytestRequest.read(SCRATCH)["problem"], "not a JSON object")


## A file that builds a script object: ConfigFile runs its _init, which writes MARKER.
class TestHostileFile:
	extends GutTest

	const MARKER := "user://test_playtest_marker.txt"

	func before_each() -> void:
		DirAccess.remove_absolute(MARKER)

	func after_each() -> void:
		for path: String in [MARKER, SCRATCH, PlaytestRequest.LEGACY_PATH]:
			DirAccess.remove_absolute(path)

	func payload() -> String:
		var source := (
			"extends RefCounted\nfunc _init():\n"
			+ '\tFileAccess.open("%s", FileAccess.WRITE).store_string("ran")\n' % MARKER
		)
		return (
			'Object(RefCounted,"script":Object(GDScript,"script/source":%s,"script":null))'
			% JSON.stringify(source)
		)

	func test_the_payload_is_live_for_configfile() -> void:
		# The control: without it, "no marker" below could pass for a payload that never works.
		Files.write_text(SCRATCH, "[playtest]\nboard=%s\n" % payload())
		ConfigFile.new().load(SCRATCH)
		assert_true(FileAccess.file_exists(MARKER), "this engine's ConfigFile runs the payload")

	func test_payload_in_the_request_file_never_runs() -> void:
		Files.write_text(SCRATCH, '[playtest]\nboard=%s\nkind="maze"\n' % payload())
		assert_eq(PlaytestRequest.take("maze", SCRATCH), "")
		assert_false(FileAccess.file_exists(MARKER), "the payload ran")
		assert_false(FileAccess.file_exists(SCRATCH), "the bad request was removed")
		assert_push_warning("not JSON")

	func test_payload_as_a_json_value_stays_text() -> void:
		var request := Files.fresh_request()
		request["board"] = payload()
		Files.write_text(SCRATCH, JSON.stringify(request))
		assert_eq(PlaytestRequest.take("maze", SCRATCH), "")
		assert_false(FileAccess.file_exists(MARKER), "the payload ran")
		assert_push_warning("the board must be a file")

	func test_old_format_request_is_removed_unread() -> void:
		Files.write_text(PlaytestRequest.LEGACY_PATH, "[playtest]\nboard=%s\n" % payload())
		assert_eq(PlaytestRequest.take("maze", SCRATCH), "")
		assert_false(FileAccess.file_exists(MARKER), "the payload ran")
		assert_false(FileAccess.file_exists(PlaytestRequest.LEGACY_PATH))
		assert_push_warning("old format")


## The play-test part of tests/fixtures/hostile_user_files/: every file is refused for the
## reason it gives (never by an engine error), removed with a warning, and no payload runs.
class TestHostileCorpus:
	extends GutTest

	const CORPUS := "res://tests/fixtures/hostile_user_files/playtest/"
	const MARKER := "user://hostile_user_files_marker.txt"
	## fixture -> a piece of the problem it must give
	const EXPECTED := {
		"configfile_payload.json": "not JSON",
		"deep_nesting.json": "too deep",
		"duplicate_keys.json": 'the key "board" is given twice',
		"gd_resource_header.json": "not JSON",
		"huge_number.json": "format must be 1",
		"invalid_utf8.json": "not UTF-8 text",
		"nan_and_inf.json": "not JSON",
		"nul_bytes.json": "NUL bytes",
		"path_escape.json": "the board must be a file",
		"payload_as_a_value.json": "the board must be a file",
		"system_file_text.json": "not JSON (line 1: Expected 'true', 'false', or 'null')",
		"two_objects.json": "not JSON",
		"utf16.json": "UTF-16",
	}

	func before_each() -> void:
		DirAccess.remove_absolute(MARKER)

	func after_each() -> void:
		for path: String in [MARKER, SCRATCH]:
			DirAccess.remove_absolute(path)

	func test_every_fixture_is_listed() -> void:
		var names := Array(DirAccess.get_files_at(CORPUS))
		names.sort()
		var listed := EXPECTED.keys()
		listed.sort()
		assert_eq(names, listed)

	func test_every_fixture_is_refused_for_its_reason_and_removed() -> void:
		for name: String in EXPECTED:
			var bytes := FileAccess.get_file_as_bytes(CORPUS + name)
			var file := FileAccess.open(SCRATCH, FileAccess.WRITE)
			file.store_buffer(bytes)
			file.close()
			assert_string_contains(PlaytestRequest.read(SCRATCH)["problem"], EXPECTED[name], name)
			assert_eq(PlaytestRequest.take("maze", SCRATCH), "", name)
			assert_false(FileAccess.file_exists(SCRATCH), "%s removed" % name)
			assert_false(FileAccess.file_exists(MARKER), "%s: the payload ran" % name)
		assert_push_warning_count(EXPECTED.size())

	func test_bom_and_crlf_requests_are_read_as_usual() -> void:
		var request := Files.fresh_request()
		var text := JSON.stringify(request, "\t").replace("\n", "\r\n")
		Files.write_text(SCRATCH, "\ufeff" + text + "\r\n")
		assert_eq(PlaytestRequest.read(SCRATCH)["problem"], "")
		assert_eq(PlaytestRequest.take("maze", SCRATCH), BOARD)
