extends GutTest
## The data-only board format: BoardTextWriter → BoardTextReader round trips every shipped
## board exactly, and the reader refuses every hostile or broken file with the field named.

const SHIPPED: Array[String] = [
	"res://levels/pachinko/classic",
	"res://levels/pachinko/tulips",
	"res://levels/pachinko/windmills",
	"res://levels/maze/classic",
	"res://levels/maze/catacombs",
	"res://levels/maze/courtyards",
]
const MARKER := "user://board_format_payload_ran.txt"


static func _shipped(stem: String) -> BoardLevel:
	for extension in [".board", ".tres"]:
		var loaded := BoardLoader.load_board(stem + extension)
		if loaded.ok():
			return loaded.level
	return null


func _tiny_pachinko_text() -> String:
	return BoardTextWriter.write(_shipped("res://levels/pachinko/classic"))


func _with(text: String, field: String, value: String) -> String:
	var regex := RegEx.create_from_string('(?m)^\\{"%s": .*\\}$' % field)
	return regex.sub(text, '{"%s": %s}' % [field, value])


func _error_of(text: String) -> String:
	var read := BoardTextReader.read(text)
	return str(read.get("error", ""))


class TestRoundTrip:
	extends "res://tests/unit/test_board_format.gd"

	func test_every_shipped_board_reads_back_as_the_same_world() -> void:
		for stem in SHIPPED:
			var level := _shipped(stem)
			assert_not_null(level, stem)
			if level == null:
				continue
			var text := BoardTextWriter.write(level)
			var read := BoardTextReader.read(text)
			assert_false(read.has("error"), "%s: %s" % [stem, read.get("error", "")])
			if read.has("error"):
				continue
			var again: BoardLevel = read["level"]
			assert_eq(BoardTextWriter.write(again), text, stem + " writes the same text twice")
			var a := BoardWorldFactory.build(level)
			var b := BoardWorldFactory.build(again)
			assert_eq(a.shapes.pin_count(), b.shapes.pin_count(), stem)
			assert_eq(a.shapes.wall_count(), b.shapes.wall_count(), stem)
			assert_eq(again.board_id, level.board_id)
			assert_eq(again.pockets.size(), level.pockets.size())
			assert_eq(again.tuning.gravity, level.tuning.gravity, "tuning keeps full precision")
			assert_eq(again.tuning.max_speed, level.tuning.max_speed)

	func test_one_item_per_line_and_rounded_coordinates() -> void:
		var level := _shipped("res://levels/pachinko/classic")
		var text := BoardTextWriter.write(level)
		var pin_lines := 0
		for line in text.split("\n"):
			if line.begins_with('{"pin": ') or line.begins_with('{"pocket": '):
				pin_lines += 1
		var field_pins := level.pin_pocket.count(-1)
		assert_eq(pin_lines, field_pins + level.pockets.size(), "a line per field pin and pocket")
		assert_false(text.contains(', "pocket": '), "a pocket's rim pins are stamped, not stored")
		level.pins[0] = Vector2(397.0096, 12.3449)
		assert_string_contains(BoardTextWriter.write(level), '"x": 397.01, "y": 12.34')

	func test_adding_a_pin_is_a_one_line_diff() -> void:
		var level := _shipped("res://levels/pachinko/classic")
		var before := BoardTextWriter.write(level).split("\n")
		level.pins.append(Vector2(100, 100))
		level.pin_pocket.append(-1)
		level.pin_special.append(0)
		var after := BoardTextWriter.write(level).split("\n")
		assert_eq(after.size(), before.size() + 1)
		var added := Array(after)
		for line in before:
			added.erase(line)
		var line := '{"pin": {"id": %d, "x": 100, "y": 100}}' % level.pins.size()
		assert_eq(added, [line], "the one new line, with the pin's new id")

	func test_a_numbers_text_never_shows_float_noise() -> void:
		assert_eq(BoardTextWriter.number(350.0), "350")
		assert_eq(BoardTextWriter.number(-0.001), "0")
		assert_eq(BoardTextWriter.number(12.5), "12.5")
		assert_eq(BoardTextWriter.number(0.1 + 0.2), "0.3")

	func test_tuning_is_one_short_line_per_constant() -> void:
		var level := _shipped("res://levels/pachinko/classic")
		var lines := BoardTextWriter.write(level).split("\n")
		var tuning := Array(lines).filter(
			func(l: String) -> bool: return l.begins_with('{"tuning"')
		)
		assert_eq(tuning.size(), BoardRanges.tuning_fields().size() - 1, "one line a constant")
		assert_has(tuning, '{"tuning": {"gravity": [0, 777.7778]}}', "a Vector2 in its own digits")
		assert_has(tuning, '{"tuning": {"min_horizontal_speed": 16.666666666666668}}')
		for line: String in lines:
			assert_lt(line.length(), 100, "no long lines: " + line.left(60))

	func test_changing_one_tuning_constant_is_a_one_line_diff() -> void:
		var level := _shipped("res://levels/pachinko/classic")
		var before := BoardTextWriter.write(level).split("\n")
		level.tuning.restitution = 0.55
		var after := BoardTextWriter.write(level).split("\n")
		assert_eq(after.size(), before.size())
		var changed := PackedStringArray()
		for i in after.size():
			if after[i] != before[i]:
				changed.append(after[i])
		assert_eq(Array(changed), ['{"tuning": {"restitution": 0.55}}'])

	func test_the_old_one_line_tuning_still_reads_the_same() -> void:
		var level := _shipped("res://levels/pachinko/classic")
		var text := BoardTextWriter.write(level)
		var old_line := (
			'{"tuning": {"ball_restitution": 0.6, "bounce_threshold": 30, "drain_slide_time": 0.5,'
			+ ' "fixed_hz": 120, "friction_against": 0, "gravity": [0, 777.7777709960938],'
			+ ' "max_speed": 1600, "min_horizontal_speed": 16.666666666666668, "rest_speed": 8,'
			+ ' "restitution": 0.6, "rolling_friction": 0, "sleep_time": 0.1, "speed_cap": 0,'
			+ ' "tangent_friction": 0.6, "tilt_gravity": 0, "wall_cap_contact": 0,'
			+ ' "wall_restitution": 0.6}}'
		)
		var kept := PackedStringArray()
		for line in text.split("\n"):
			if line.begins_with('{"tuning": {"ball_restitution"'):
				kept.append(old_line)
			elif not line.begins_with('{"tuning"'):
				kept.append(line)
		var read := BoardTextReader.read("\n".join(kept))
		assert_false(read.has("error"), str(read.get("error", "")))
		if read.has("error"):
			return
		var old: BoardLevel = read["level"]
		assert_eq(BoardTextWriter.write(old), text, "the old form reads to the very same board")

	func test_a_tuning_constant_given_twice_is_refused() -> void:
		var text := _tiny_pachinko_text() + '{"tuning": {"restitution": 0.5}}\n'
		assert_string_contains(_error_of(text), 'tuning "restitution" is given twice')


class TestHostile:
	extends "res://tests/unit/test_board_format.gd"

	func test_object_constructors_are_only_text_and_are_refused() -> void:
		var payload := 'Object(GDScript,"script/source":"func _init(): pass")'
		var text := _with(_tiny_pachinko_text(), "ring_radius", JSON.stringify(payload))
		assert_string_contains(_error_of(text), "ring_radius")
		text = _with(_tiny_pachinko_text(), "display_name", JSON.stringify(payload))
		assert_eq(_error_of(text), "", "a name may hold any text; it is never run")
		assert_false(FileAccess.file_exists(MARKER))

	func test_nan_inf_and_huge_numbers_name_the_field() -> void:
		var base := _tiny_pachinko_text()
		assert_string_contains(_error_of(_with(base, "ring_radius", "NaN")), "JSON")
		assert_string_contains(_error_of(_with(base, "ring_radius", "1e400")), "finite")
		assert_string_contains(_error_of(_with(base, "ring_radius", "1e7")), "ring_radius")
		assert_string_contains(
			_error_of(_with(base, "cup_start_balls", "9223372036854775807")), "cup"
		)
		var tuned := base.replace('"restitution": 0.6', '"restitution": 5')
		assert_string_contains(_error_of(tuned), "restitution")
		tuned = base.replace('"sleep_time": 0.1', '"sleep_time": -1e30')
		assert_string_contains(_error_of(tuned), "sleep_time")

	func test_structure_problems() -> void:
		assert_string_contains(_error_of("[".repeat(200000)), "JSON")
		assert_string_contains(_error_of("[1, 2]"), "object")
		assert_string_contains(_error_of(""), "format")
		assert_string_contains(_error_of('{"format": "x"}'), "format")
		var base := _tiny_pachinko_text()
		assert_string_contains(_error_of(base + '{"extra": 1}'), "extra")
		assert_string_contains(_error_of(base + '{"ring_radius": 300}'), "twice")
		assert_string_contains(_error_of(base + '{"pins": []}'), "one per line")
		assert_string_contains(
			_error_of(base.replace('"format_version": 1', '"format_version": 99')), "newer"
		)
		assert_string_contains(_error_of(base.replace('"x": ', '"script": 1, "x": ')), "script")
		assert_string_contains(_error_of(base + '{"pin": {"x": 1, "y": 2}, "hole": 1}'), "alone")
		var with_nul := (base + "{}").to_utf8_buffer()
		with_nul[with_nul.size() - 1] = 0
		assert_string_contains(str(BoardTextReader.read_bytes(with_nul).get("error")), "NUL")

	func test_bom_and_crlf_are_fine() -> void:
		var base := _tiny_pachinko_text()
		assert_eq(_error_of(char(0xFEFF) + base), "")
		assert_eq(_error_of(base.replace("\n", "\r\n")), "")

	func test_huge_counts_are_refused_before_building() -> void:
		var text := _tiny_pachinko_text() + '{"pin": {"x": 1, "y": 1}}\n'.repeat(6000)
		assert_string_contains(_error_of(text), "at most 5000")
		text = _tiny_pachinko_text() + "\n".repeat(20000)
		assert_string_contains(_error_of(text), "lines")


class TestPaths:
	extends "res://tests/unit/test_board_format.gd"

	func test_paths_outside_the_board_folders_are_refused() -> void:
		assert_string_contains(BoardLoader.path_problem("res://../etc/x.board"), "load only from")
		assert_string_contains(BoardLoader.path_problem("res://levels/../project.board"), "'..'")
		assert_string_contains(BoardLoader.path_problem("/etc/passwd"), "load only from")
		assert_string_contains(BoardLoader.path_problem("user://settings.board"), "load only from")
		assert_eq(BoardLoader.path_problem("res://levels/pachinko/classic.board"), "")

	func test_a_symlink_in_the_player_folder_is_refused() -> void:
		DirAccess.make_dir_recursive_absolute("user://boards")
		var link := ProjectSettings.globalize_path("user://boards/link_test.board")
		DirAccess.remove_absolute(link)
		var made := OS.execute("ln", ["-s", "/etc/hostname", link])
		if made != 0:
			pass_test("no ln here")
			return
		assert_string_contains(BoardLoader.path_problem("user://boards/link_test.board"), "link")
		DirAccess.remove_absolute(link)


class TestSaver:
	extends "res://tests/unit/test_board_format.gd"

	func test_saving_an_unchanged_board_writes_nothing() -> void:
		var level := _shipped("res://levels/maze/classic")
		var path := "user://saver_test.board"
		assert_eq(ResourceSaver.save(level, path), OK)
		var first := FileAccess.get_modified_time(path)
		var text := FileAccess.get_file_as_string(path)
		OS.delay_msec(1100)
		assert_eq(ResourceSaver.save(level, path), OK)
		assert_eq(FileAccess.get_modified_time(path), first, "the file was not rewritten")
		assert_eq(FileAccess.get_file_as_string(path), text)
		var loaded := ResourceLoader.load(path, "", ResourceLoader.CACHE_MODE_IGNORE)
		assert_true(loaded is BoardLevel, "Godot loads .board files through BoardFormatLoader")
		DirAccess.remove_absolute(path)
