extends GutTest
## A key given twice in one JSON object is found wherever it hides (nested, in a list, spelt
## with an escape), a repeat in different objects is not one, and the settings reader refuses
## a value that holds one instead of keeping the last.


func test_a_repeat_is_found_at_any_depth() -> void:
	assert_eq(JsonKeys.repeated('{"a": 1, "a": 2}'), "a")
	assert_eq(JsonKeys.repeated('{"pin": {"x": 1, "y": 2, "x": 3}}'), "x")
	assert_eq(JsonKeys.repeated('[1, {"b": [{"c": 1, "c": 2}]}]'), "c")
	assert_eq(JsonKeys.repeated('{"a_b": 1, "a\\u005fb": 2}'), "a_b", "an escape is the same key")


func test_the_same_key_in_different_objects_is_fine() -> void:
	assert_eq(JsonKeys.repeated('[{"a": 1}, {"a": 2}]'), "")
	assert_eq(JsonKeys.repeated('{"a": {"a": {"a": 1}}, "b": "a"}'), "")
	assert_eq(JsonKeys.repeated('{"a": "x\\", \\"a\\": 1", "b": 2}'), "", "quotes inside a value")
	assert_eq(JsonKeys.repeated('{"a\\\\": 1, "a": 2}'), "", "an escaped backslash ends the key")
	assert_eq(JsonKeys.repeated('["a", "a"]'), "", "strings in a list are not keys")


func test_the_problem_names_the_key_short_and_escaped() -> void:
	assert_eq(JsonKeys.problem("seed"), 'the key "seed" is given twice')
	var long := "k".repeat(500)
	assert_lt(JsonKeys.problem(long).length(), 80)
	assert_false(JsonKeys.problem("a\nb").contains("\n"), "no line break from the file")


func test_a_settings_value_with_a_repeated_key_is_refused() -> void:
	var read := IniText.parse('[audio]\nmaster_volume={"v": 0.5, "v": 0.25}\nsfx_volume=0.5\n')
	var audio: Dictionary = read["sections"]["audio"]
	assert_false(audio.has("master_volume"), "the value is not kept")
	assert_eq(audio.get("sfx_volume"), 0.5)
	assert_eq(read["problems"], PackedStringArray(["master_volume (line 2)"]))


func test_the_parsed_shortcut_gives_the_same_answers() -> void:
	for text: String in [
		'{"a": 1, "a": 2}',
		'{"a": "x:y", "b": 2}',
		'{"a": "x:y", "a": 2}',
		'{"p": {"x": 1, "y": 2, "x": 3}}',
		'[{"a": 1}, {"a": 2}]',
		'{"a" : 1, "b" : {"c": [1, 2]}}',
	]:
		assert_eq(JsonKeys.repeated(text, JSON.parse_string(text)), JsonKeys.repeated(text), text)


func test_a_repeat_is_found_however_the_json_is_spaced() -> void:
	assert_eq(JsonKeys.repeated('{"a":1,"a":2}'), "a", "no spaces at all")
	assert_eq(JsonKeys.repeated('{"a" :1, "a"\t:2}'), "a", "space or tab before the colon")
	assert_eq(JsonKeys.repeated('{\n"a"\r\n:\n1,\n"a"\n:2}'), "a", "line breaks")
	assert_eq(JsonKeys.repeated('{"x":{"k":"v"},"x":1}'), "x", "a value string before }")
	assert_eq(JsonKeys.repeated('{"x":["v"],"x":1}'), "x", "a list string before ]")


func test_a_repeat_after_a_nested_list_or_object_is_still_found() -> void:
	assert_eq(JsonKeys.repeated('{"a": [1, {"b": 1}], "a": 2}'), "a")
	assert_eq(JsonKeys.repeated('{"a": [1], "a": 2}'), "a")
	assert_eq(JsonKeys.repeated('{"a": {"b": [1, 2]}, "c": 3, "a": 4}'), "a")
	assert_eq(JsonKeys.repeated('[[1, 2], {"k": 1, "k": 2}]'), "k")


func test_keys_of_a_closed_object_do_not_count_against_its_parent() -> void:
	assert_eq(JsonKeys.repeated('{"x": {"a": 1}, "a": 2}'), "")
	assert_eq(JsonKeys.repeated('{"x": [{"a": 1}], "a": 2}'), "")
	assert_eq(JsonKeys.repeated('{"x": [{"a": 1}], "y": {"a": 2}}'), "")
	assert_eq(JsonKeys.repeated('{"a": "x", "c": "x"}'), "", "equal values are no repeat")
	assert_eq(JsonKeys.repeated('{"ab": 1, "ac": 2, "abc": 3}'), "", "keys alike but not equal")
	assert_eq(JsonKeys.repeated('{"": 1, "a": 1, "a": 2}'), "a", "an empty key before a repeat")


func test_escaped_quotes_and_backslashes_in_keys() -> void:
	assert_eq(JsonKeys.repeated('{"a\\"b": 1, "a\\"b": 2}'), 'a"b')
	assert_eq(JsonKeys.repeated('{"a\\\\": 1, "a\\\\": 2}'), "a\\")
	assert_eq(JsonKeys.repeated('{"a\\\\\\"": 1, "a\\\\\\"": 2}'), 'a\\"')
	assert_eq(JsonKeys.repeated('{"q\\"": 1, "q": 2}'), "", 'q" and q differ')
	assert_eq(JsonKeys.repeated('{"\\\\\\\\": 1, "\\\\": 2}'), "", "two backslashes, then one")


func test_a_bare_json_string_or_list_has_no_keys() -> void:
	assert_eq(JsonKeys.repeated('"a,b"'), "")
	assert_eq(JsonKeys.repeated('"a,b"', "a,b"), "")
	assert_eq(JsonKeys.repeated('["a", "b"]', ["a", "b"]), "")


func test_the_parsed_shortcut_never_hides_a_repeat() -> void:
	for text: String in [
		'{"a": 1, "a": 2}',
		'{"a": [1, 2], "a": 3}',
		'{"a": {"b": 1}, "a": 2}',
		'[{"a": 1, "a": [1]}]',
		'{"a": "x", "a": "y"}',
	]:
		assert_eq(JsonKeys.repeated(text, JSON.parse_string(text)), "a", text)


func test_a_long_key_is_cut_at_forty_characters() -> void:
	var forty := "k".repeat(40)
	assert_eq(JsonKeys.problem(forty), 'the key "%s" is given twice' % forty, "40 shown whole")
	assert_eq(JsonKeys.problem(forty + "x"), 'the key "%s…" is given twice' % forty, "41 cut to 40")
	assert_eq(JsonKeys.problem('a"b\n'), 'the key "a\\"b\\n" is given twice')


# A repeated empty key was answered "" (no repeat), so {"": 1, "": 2} loaded with the
# second value quietly winning (found by the mutation work of issue 45).
func test_a_repeated_empty_key_is_found_and_named() -> void:
	assert_eq(JsonKeys.repeated('{"": 1, "": 2}'), JsonKeys.EMPTY_KEY)
	assert_eq(JsonKeys.repeated('{"a": {"": 1, "": 2}}', {"a": {"": 2}}), JsonKeys.EMPTY_KEY)
	assert_eq(JsonKeys.repeated('{"": 1, "b": 2}'), "", "one empty key is no repeat")
	assert_eq(JsonKeys.problem(JsonKeys.EMPTY_KEY), 'the empty key "" is given twice')
