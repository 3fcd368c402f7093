extends GutTest
## The player's files (settings.cfg, save.cfg) as text: what a line must look like to be
## read, what a broken line is called in the message the player sees, and that every key
## and value written reads back the same.

const DIR := "user://test_ini_text"


func before_each() -> void:
	DirAccess.make_dir_recursive_absolute(DIR)


func after_each() -> void:
	for name in DirAccess.get_files_at(DIR):
		DirAccess.remove_absolute(DIR.path_join(name))
	DirAccess.remove_absolute(DIR)


func _write(name: String, text: String) -> String:
	var path := DIR.path_join(name)
	var file := FileAccess.open(path, FileAccess.WRITE)
	file.store_string(text)
	file.close()
	return path


func test_sections_keys_and_values_are_read() -> void:
	var text := "; a comment\n# another\n\n[ audio ]\nmaster = 0.5\nmuted=true\n[video]\nsize=[1, 2]\n"
	var read := IniText.parse(text)
	assert_eq(
		read["sections"], {"audio": {"master": 0.5, "muted": true}, "video": {"size": [1.0, 2.0]}}
	)
	assert_eq(read["problems"], PackedStringArray())
	assert_eq(read["problem_count"], 0)


func test_a_section_given_twice_keeps_both_halves() -> void:
	var read := IniText.parse("[a]\nx=1\n[b]\ny=2\n[a]\nz=3\nx=4\n")
	assert_eq(read["sections"]["a"], {"x": 4.0, "z": 3.0}, "the later value of a key counts")
	assert_eq(read["sections"]["b"], {"y": 2.0})


func test_a_windows_file_reads_the_same() -> void:
	var read := IniText.parse("[audio]\r\nmaster=0.5\r\n")
	assert_eq(read["sections"], {"audio": {"master": 0.5}})


func test_each_broken_line_is_named_with_its_number() -> void:
	var text := "x=1\n[audio\n[]\nlost=1\n[ok]\nno equals here\n=5\nvolume=loud\n"
	var read := IniText.parse(text)
	assert_eq(
		read["problems"],
		PackedStringArray(
			[
				"line 1 (outside a [section])",
				"line 2 (not a [section])",
				"line 3 (not a [section])",
				"line 4 (outside a [section])",
				"line 6 (no =)",
			]
		)
	)
	assert_eq(read["problem_count"], 7, "the sixth and seventh are counted, not listed")
	assert_eq(read["sections"], {"ok": {}})


func test_a_broken_value_is_named_by_its_key() -> void:
	var read := IniText.parse("[a]\nfine=1\nvolume=loud\n")
	assert_eq(read["problems"], PackedStringArray(["volume (line 3)"]))
	assert_eq(read["sections"]["a"], {"fine": 1.0})
	var odd := IniText.parse("[a]\n100% sure=nope\n")
	assert_eq(odd["problems"], PackedStringArray(["100% sure (line 2)"]), "a % shows as typed")
	var long := IniText.parse("[a]\n%s=nope\n" % "k".repeat(60))
	assert_eq(long["problems"], PackedStringArray(["%s (line 2)" % "k".repeat(40)]))


func test_a_line_after_a_broken_header_is_outside_any_section() -> void:
	var read := IniText.parse("[a]\nx=1\n[broken\ny=2\n")
	assert_eq(read["sections"], {"a": {"x": 1.0}}, "y does not land in the section above")
	assert_eq(
		read["problems"],
		PackedStringArray(["line 3 (not a [section])", "line 4 (outside a [section])"])
	)


func test_quoted_keys() -> void:
	var read := IniText.parse('[a]\n"x=y"=1\n"say \\"hi\\""=2\n"b\\\\"=3\n')
	assert_eq(read["sections"]["a"], {"x=y": 1.0, 'say "hi"': 2.0, "b\\": 3.0})
	var edges := IniText.parse('[a]\n""=1\n"\\"q\\""=2\n')
	assert_eq(
		edges["sections"]["a"], {"": 1.0, '"q"': 2.0}, "an empty key, a key opening with a quote"
	)
	var after_text := IniText.parse('[a]\n"ok"="v"\n"\\x"=2\n')
	assert_eq(
		after_text["sections"]["a"], {"ok": "v"}, "the bad key does not borrow the last value"
	)
	assert_eq(
		after_text["problems"], PackedStringArray(["line 3 (a quoted key must be one JSON string)"])
	)
	var bad_escape := IniText.parse('[a]\n"\\x"=1\n')
	assert_eq(
		bad_escape["problems"], PackedStringArray(["line 2 (a quoted key must be one JSON string)"])
	)
	var broken := IniText.parse('[a]\n"open=1\n"k" 1\n"k"\n')
	assert_eq(
		broken["problems"],
		PackedStringArray(
			[
				"line 2 (a quoted key must be one JSON string)",
				"line 3 (no = after the key)",
				"line 4 (no = after the key)",
			]
		)
	)


func test_a_value_with_a_key_given_twice_is_refused() -> void:
	var read := IniText.parse('[a]\nv={"k": 1, "k": 2}\nw={"k": 1}\n')
	assert_eq(read["sections"]["a"], {"w": {"k": 1.0}})
	assert_eq(read["problems"], PackedStringArray(["v (line 2)"]))


func test_keys_are_written_bare_only_when_plain() -> void:
	assert_eq(IniText.key_text("master_volume"), "master_volume")
	assert_eq(IniText.key_text("board.v2-b"), "board.v2-b")
	assert_eq(IniText.key_text("_x"), "_x")
	assert_eq(IniText.key_text("9lives"), "9lives")
	assert_eq(IniText.key_text("a b"), '"a b"')
	assert_eq(IniText.key_text("a=b"), '"a=b"')
	assert_eq(IniText.key_text("-a"), '"-a"')
	assert_eq(IniText.key_text(".a"), '".a"')
	assert_eq(IniText.key_text("a]"), '"a]"')
	assert_eq(IniText.key_text(""), '""')


func test_the_written_file_reads_back_the_same() -> void:
	var odd_keys := {
		"plain": 1.0,
		"with = and ] and ;": "x",
		'"quoted"': [1.0, 2.0],
		"line\nbreak": true,
		"tab\tand\u0001bell\u007f": "\u0001\u007f",
		"ünïcödé ✓": 0.25,
	}
	var text := IniText.format(
		"Board Studio\nsecond line", [["meta", {"version": 1}], ["k", odd_keys]]
	)
	assert_true(
		text.begins_with("; Board Studio\n; second line\n\n[meta]\nversion=1\n\n[k]\n"), text
	)
	assert_true(text.ends_with("\n"))
	assert_false(text.contains("\u0001") or text.contains("\u007f"), "control characters escaped")
	assert_eq(text.count("\n"), 13, "one line a key: no raw line break from a key or value")
	var read := IniText.parse(text)
	assert_eq(read["problems"], PackedStringArray())
	assert_eq(read["sections"]["meta"], {"version": 1.0})
	assert_eq(read["sections"]["k"], odd_keys)


func test_a_lone_control_character_is_escaped_too() -> void:
	var unit := IniText.format("h", [["s", {"k": "x\u001fy"}]])
	assert_string_contains(unit, 'k="x\\u001fy"', "the last one below a space")
	var delete := IniText.format("h", [["s", {"k": "x\u007fy"}]])
	assert_string_contains(delete, 'k="x\\u007fy"', "DEL")


func test_control_characters_are_written_as_escapes() -> void:
	var text := IniText.format("h", [["s", {"k": "a\u0001b\u001f\u007fc\u0020"}]])
	assert_string_contains(text, 'k="a\\u0001b\\u001f\\u007fc "')


func test_a_versioned_file_gives_its_version_and_its_problems() -> void:
	var path := _write("ok.cfg", "[meta]\nversion=3\n[s]\nbad\nx=1\n")
	var read := IniText.read_versioned_file(path)
	assert_eq(read["version"], 3)
	assert_eq(read["sections"]["s"], {"x": 1.0})
	assert_eq(read["problems"], PackedStringArray(["line 4 (no =)"]))


func test_a_versioned_file_with_many_problems_counts_the_rest() -> void:
	var path := _write("many.cfg", "[meta]\nversion=1\n[s]\n" + "bad\n".repeat(8))
	var problems: PackedStringArray = IniText.read_versioned_file(path)["problems"]
	assert_eq(problems.size(), 6)
	assert_eq(problems[0], "line 4 (no =)")
	assert_eq(problems[5], "3 more lines")
	var six := _write("six.cfg", "[meta]\nversion=1\n[s]\n" + "bad\n".repeat(6))
	var with_one: PackedStringArray = IniText.read_versioned_file(six)["problems"]
	assert_eq(with_one[5], "1 more lines", "one past the five listed is counted")
	var five := _write("five.cfg", "[meta]\nversion=1\n[s]\n" + "bad\n".repeat(5))
	var listed: PackedStringArray = IniText.read_versioned_file(five)["problems"]
	assert_eq(listed.size(), 5, "all five listed, no 'more lines'")


func test_a_file_without_a_version_is_refused_naming_its_first_bad_line() -> void:
	var none := IniText.read_versioned_file(_write("none.cfg", "[s]\nx=1\n"))
	assert_eq(none, {"error": "it has no [meta] version line"})
	var bad := IniText.read_versioned_file(_write("bad.cfg", "garbage\n[s]\nmore garbage\n"))
	assert_eq(
		bad, {"error": "it has no [meta] version line; unreadable: line 1 (outside a [section])"}
	)
	assert_eq(IniText.read_versioned_file(DIR.path_join("absent.cfg")), {"missing": true})


func test_a_written_file_reads_back() -> void:
	var path := DIR.path_join("written.cfg")
	var text := IniText.format("h", [["meta", {"version": 2}], ["s", {"a": "b"}]])
	assert_eq(IniText.write_file(path, text), OK)
	var read := IniText.read_file(path)
	assert_eq(read["sections"], {"meta": {"version": 2.0}, "s": {"a": "b"}})
	assert_eq(IniText.read_file(DIR.path_join("absent.cfg")), {"missing": true})
