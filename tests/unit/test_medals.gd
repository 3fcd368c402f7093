extends GutTest
## Medal times: the optional `medal_times` field of a maze file (read, written, refused when
## wrong) and the medal a best time earns.

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
	return BoardTextReader.read(_classic_text() + line + "\n")


func test_medal_times_round_trip_through_the_file() -> void:
	var level: BoardLevel = BoardTextReader.read(_classic_text())["level"]
	level.medal_times_easy = PackedFloat64Array([44.3, 60.5, 88.7])
	level.medal_times_hard = PackedFloat64Array([50.0, 68.2, 100.0])
	var text := BoardTextWriter.write(level)
	assert_string_contains(
		text, '{"medal_times": {"easy": [44.3, 60.5, 88.7], "hard": [50, 68.2, 100]}}'
	)
	var again: BoardLevel = BoardTextReader.read(text)["level"]
	assert_eq(again.medal_times_easy, level.medal_times_easy)
	assert_eq(again.medal_times_hard, level.medal_times_hard)
	assert_eq(BoardTextWriter.write(again), text, "the same board writes the same text")


func test_the_field_is_optional_and_one_mode_may_be_left_out() -> void:
	var level: BoardLevel = BoardTextReader.read(_classic_text())["level"]
	assert_true(level.medal_times_easy.is_empty())
	assert_false(
		BoardTextWriter.write(level).contains("medal_times"), "no line when there are none"
	)
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
		var result := BoardTextReader.read(text + line + "\n")
		assert_true(result.has("error"), line)
		assert_string_contains(str(result.get("error", "")), cases[line], line)
		assert_string_contains(str(result.get("error", "")), "medal_times", line)


func test_a_pachinko_board_has_no_medal_times() -> void:
	var text := FileAccess.get_file_as_string("res://levels/pachinko/classic.board")
	var result := BoardTextReader.read(text + '{"medal_times": {"easy": [1, 2, 3]}}\n')
	assert_string_contains(str(result.get("error", "")), 'unknown field "medal_times"')


func test_medal_for_a_time() -> void:
	var times := Medals.from_pilot_time(40.0)
	assert_eq(
		times,
		PackedFloat64Array([60.0, 108.0, 210.0]),
		"gold 1.5 x the pilot, silver 1.8 x gold, bronze 3.5 x gold"
	)
	assert_eq(Medals.from_pilot_time(40.01)[0], 60.1, "rounded up to a tenth")
	assert_eq(Medals.medal_for_time(times, 59.9), Medals.Medal.GOLD)
	assert_eq(Medals.medal_for_time(times, 60.0), Medals.Medal.GOLD)
	assert_eq(Medals.medal_for_time(times, 108.0), Medals.Medal.SILVER)
	assert_eq(Medals.medal_for_time(times, 108.1), Medals.Medal.BRONZE)
	assert_eq(Medals.medal_for_time(times, 210.0), Medals.Medal.BRONZE)
	assert_eq(Medals.medal_for_time(times, 210.1), Medals.Medal.NONE)
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


# A level with easy medal times [10, 20, 30] and hard ones [15, 25, 40].
func _level_with_times() -> BoardLevel:
	var level := BoardLevel.new()
	level.medal_times_easy = PackedFloat64Array([10.0, 20.0, 30.0])
	level.medal_times_hard = PackedFloat64Array([15.0, 25.0, 40.0])
	return level


func test_each_medal_time_is_the_last_second_that_earns_it() -> void:
	var times := PackedFloat64Array([10.0, 20.0, 30.0])
	assert_eq(Medals.medal_for_time(times, 10.0), Medals.Medal.GOLD, "gold time itself")
	assert_eq(Medals.medal_for_time(times, 10.1), Medals.Medal.SILVER, "a tenth over gold")
	assert_eq(Medals.medal_for_time(times, 20.0), Medals.Medal.SILVER, "silver time itself")
	assert_eq(Medals.medal_for_time(times, 20.1), Medals.Medal.BRONZE, "a tenth over silver")
	assert_eq(Medals.medal_for_time(times, 30.0), Medals.Medal.BRONZE, "bronze time itself")
	assert_eq(Medals.medal_for_time(times, 30.1), Medals.Medal.NONE, "a tenth over bronze")
	assert_eq(Medals.medal_for_time(times, 0.1), Medals.Medal.GOLD, "any finish under gold")


# A play trial finished in 22.833 s against a 22.8 s gold: the clock said 0:22.8, the card
# said Silver, "0.1 s short of Gold". The medal is judged on the time the clock shows.
func test_a_time_the_clock_shows_as_the_gold_time_earns_gold() -> void:
	var times := PackedFloat64Array([22.8, 30.0, 40.0])
	assert_eq(Medals.medal_for_time(times, 22.833), Medals.Medal.GOLD, "the clock shows 0:22.8")
	assert_eq(Medals.medal_for_time(times, 22.899), Medals.Medal.GOLD, "still 0:22.8")
	assert_eq(Medals.medal_for_time(times, 22.9), Medals.Medal.SILVER, "0:22.9 is over")
	assert_eq(Medals.medal_for_time(times, 36.3), Medals.Medal.BRONZE, "36.3 stays 36.3")


func test_no_finish_and_broken_times_earn_no_medal() -> void:
	var times := PackedFloat64Array([10.0, 20.0, 30.0])
	assert_eq(Medals.medal_for_time(times, 0.0), Medals.Medal.NONE, "0 s is no finish")
	assert_eq(Medals.medal_for_time(times, INF), Medals.Medal.NONE)
	assert_eq(Medals.medal_for_time(times, NAN), Medals.Medal.NONE)
	assert_eq(Medals.medal_for_time(PackedFloat64Array([10.0, 20.0]), 5.0), Medals.Medal.NONE)
	var four := PackedFloat64Array([10.0, 20.0, 30.0, 40.0])
	assert_eq(Medals.medal_for_time(four, 5.0), Medals.Medal.NONE, "four times are no medal set")


func test_the_pilot_time_sets_each_medal_rounded_up_to_a_tenth() -> void:
	assert_eq(Medals.from_pilot_time(10.0), PackedFloat64Array([15.0, 27.0, 52.5]))
	assert_eq(Medals.from_pilot_time(10.01), PackedFloat64Array([15.1, 27.1, 52.6]))
	assert_eq(Medals.from_pilot_time(0.0), PackedFloat64Array([0.0, 0.0, 0.0]))


func test_a_best_time_is_judged_against_its_own_mode() -> void:
	var level := _level_with_times()
	assert_eq(Medals.times_for(level, false), PackedFloat64Array([10.0, 20.0, 30.0]))
	assert_eq(Medals.times_for(level, true), PackedFloat64Array([15.0, 25.0, 40.0]))
	assert_eq(Medals.times_for(null, true), PackedFloat64Array(), "no board, no times")
	assert_eq(Medals.medal(level, false, 12.0), Medals.Medal.SILVER, "easy: 12 s is silver")
	assert_eq(Medals.medal(level, true, 12.0), Medals.Medal.GOLD, "hard: 12 s is gold")
	assert_eq(Medals.medal(level, true, 35.0), Medals.Medal.BRONZE)
	assert_eq(Medals.medal(level, false, -1.0), Medals.Medal.NONE, "never finished")
	assert_eq(Medals.medal(null, false, 5.0), Medals.Medal.NONE, "no board")


func test_every_medal_has_its_name() -> void:
	assert_eq(Medals.name_of(Medals.Medal.NONE), "No medal")
	assert_eq(Medals.name_of(Medals.Medal.BRONZE), "Bronze")
	assert_eq(Medals.name_of(Medals.Medal.SILVER), "Silver")
	assert_eq(Medals.name_of(Medals.Medal.GOLD), "Gold")


func test_the_side_panel_shows_the_best_medal_still_in_reach() -> void:
	var times := PackedFloat64Array([10.0, 20.0, 30.0])
	assert_eq(Medals.next_target(times, 0.0), {"medal": Medals.Medal.GOLD, "seconds": 10.0})
	assert_eq(Medals.next_target(times, 10.0), {"medal": Medals.Medal.GOLD, "seconds": 10.0})
	assert_eq(Medals.next_target(times, 10.5), {"medal": Medals.Medal.SILVER, "seconds": 20.0})
	assert_eq(Medals.next_target(times, 20.0), {"medal": Medals.Medal.SILVER, "seconds": 20.0})
	assert_eq(Medals.next_target(times, 25.0), {"medal": Medals.Medal.BRONZE, "seconds": 30.0})
	assert_eq(Medals.next_target(times, 30.0), {"medal": Medals.Medal.BRONZE, "seconds": 30.0})
	assert_eq(Medals.next_target(times, 30.5), {"medal": Medals.Medal.NONE, "seconds": 0.0})
	var none := {"medal": Medals.Medal.NONE, "seconds": 0.0}
	assert_eq(Medals.next_target(PackedFloat64Array(), 1.0), none, "a board without times")
	assert_eq(Medals.next_target(PackedFloat64Array([10.0, 20.0]), 1.0), none)


func test_the_time_each_medal_asks_for() -> void:
	var times := PackedFloat64Array([10.0, 20.0, 30.0])
	assert_eq(Medals.time_of(times, Medals.Medal.GOLD), 10.0)
	assert_eq(Medals.time_of(times, Medals.Medal.SILVER), 20.0)
	assert_eq(Medals.time_of(times, Medals.Medal.BRONZE), 30.0)
	assert_eq(Medals.time_of(times, Medals.Medal.NONE), -1.0, "no medal asks for no time")
	assert_eq(Medals.time_of(PackedFloat64Array(), Medals.Medal.GOLD), -1.0, "no times")
	var two := PackedFloat64Array([10.0, 20.0])
	assert_eq(Medals.time_of(two, Medals.Medal.GOLD), -1.0, "not a set of three")
