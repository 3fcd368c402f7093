extends GutTest
## A key given twice in one JSON object is found wherever it hides (nested, in a list, spelt
## with an escape), a repeat in different objects is not one, and the settings reader refuses
## a value that holds one instead of keeping the last.

const IniText := preload("res://scripts/app/ini_text.gd")


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
