extends GutTest
## Medal times: the optional `medal_times` field of a maze file (read, written, refused when
## wrong) and the medal a best time earns.

const Reader := preload("res://scripts/loading/board_text_reader.gd")
const Writer := preload("res://scripts/loading/board_text_writer.gd")
const CLASSIC := "res://levels/maze/classic.board"


# The classic board's text without any medal times line.
func _classic_text() -> String:
	var lines := FileAccess.get_file_as_string(CLASSIC).split("\n")
	var kept := PackedStringArray()
	for line in lines:
		if not line.contains("medal_times"):
			kept.append(line)
	return "\n".join(kept)


func _with_line(line: String) -> Dictionary:
	return Reader.read(_classic_text() + line + "\n")


func test_medal_times_round_trip_through_the_file() -> void:
	var level: BoardLevel = Reader.read(_classic_text())["level"]
	level.medal_times_easy = PackedFloat64Array([44.3, 60.5, 88.7])
	level.medal_times_hard = PackedFloat64Array([50.0, 68.2, 100.0])
	var text := Writer.write(level)
	assert_string_contains(
		text, '{"medal_times": {"easy": [44.3, 60.5, 88.7], "hard": [50, 68.2, 100]}}'
	)
	var again: BoardLevel = Reader.read(text)["level"]
	assert_eq(again.medal_times_easy, level.medal_times_easy)
	assert_eq(again.medal_times_hard, level.medal_times_hard)
	assert_eq(Writer.write(again), text, "the same board writes the same text")


func test_the_field_is_optional_and_one_mode_may_be_left_out() -> void:
	var level: BoardLevel = Reader.read(_classic_text())["level"]
	assert_true(level.medal_times_easy.is_empty())
	assert_false(Writer.write(level).contains("medal_times"), "no line when there are none")
	var easy_only: BoardLevel = _with_line('{"medal_times": {"easy": [10, 20, 30]}}')["level"]
	if easy_only == null:
		fail_test("a board with only easy medal times loads")
		return
	assert_eq(easy_only.medal_times_easy, PackedFloat64Array([10, 20, 30]))
	assert_true(easy_only.medal_times_hard.is_empty())


func test_bad_medal_times_are_refused_by_name() -> void:
	var text := _classic_text()
	var cases := {
		'{"medal_times": [1, 2, 3]}': "must be an object",
		'{"medal_times": {"expert": [1, 2, 3]}}': 'unknown mode "expert"',
		'{"medal_times": {"easy": [1, 2]}}': "three times",
		'{"medal_times": {"easy": [30, 20, 10]}}': "must not get faster",
		'{"medal_times": {"hard": [-1, 2, 3]}}': "between",
		'{"medal_times": {"easy": ["a", 2, 3]}}': "must be a number",
	}
	for line: String in cases:
		var result := Reader.read(text + line + "\n")
		assert_true(result.has("error"), line)
		assert_string_contains(str(result.get("error", "")), cases[line], line)
		assert_string_contains(str(result.get("error", "")), "medal_times", line)


func test_a_pachinko_board_has_no_medal_times() -> void:
	var text := FileAccess.get_file_as_string("res://levels/pachinko/classic.board")
	var result := Reader.read(text + '{"medal_times": {"easy": [1, 2, 3]}}\n')
	assert_string_contains(str(result.get("error", "")), 'unknown field "medal_times"')


func test_medal_for_a_time() -> void:
	var times := Medals.from_pilot_time(40.0)
	assert_eq(times, PackedFloat64Array([60.0, 88.0, 140.0]), "1.5, 2.2 and 3.5 x the pilot")
	assert_eq(Medals.from_pilot_time(40.01)[0], 60.1, "rounded up to a tenth")
	assert_eq(Medals.medal_for_time(times, 59.9), Medals.Medal.GOLD)
	assert_eq(Medals.medal_for_time(times, 60.0), Medals.Medal.GOLD)
	assert_eq(Medals.medal_for_time(times, 70.0), Medals.Medal.SILVER)
	assert_eq(Medals.medal_for_time(times, 140.0), Medals.Medal.BRONZE)
	assert_eq(Medals.medal_for_time(times, 140.1), Medals.Medal.NONE)
	assert_eq(Medals.medal_for_time(times, -1.0), Medals.Medal.NONE, "never finished")
	assert_eq(Medals.medal_for_time(PackedFloat64Array(), 10.0), Medals.Medal.NONE)
	assert_eq(Medals.name_of(Medals.Medal.SILVER), "Silver")


func test_every_shipped_maze_has_medal_times_for_both_modes() -> void:
	for loaded in BoardLoader.list_boards(BoardLevel.Kind.MAZE):
		assert_true(loaded.ok(), loaded.error)
		if not loaded.ok():
			continue
		assert_eq(loaded.level.medal_times_easy.size(), 3, loaded.path)
		assert_eq(loaded.level.medal_times_hard.size(), 3, loaded.path)
