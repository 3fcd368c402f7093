extends GutTest
## Medal times come from the pilot's play: every shipped maze board's file holds the times
## MedalRule makes from what tools/maze_pilot_table.gd --write-medals measured on that very
## board (MedalRule.PILOT_RECORD, with the board's fingerprint), hard differs from easy on
## every board with holes, and the record is what the pilot really does (one board replayed).

const MAZE_DIR := "res://levels/maze/"


func _record() -> Dictionary:
	var parsed: Variant = JSON.parse_string(FileAccess.get_file_as_string(MedalRule.PILOT_RECORD))
	return parsed if parsed is Dictionary else {}


func _boards() -> Array[String]:
	var out: Array[String] = []
	for file in DirAccess.get_files_at(MAZE_DIR):
		if file.ends_with(".board"):
			out.append(MAZE_DIR + file)
	out.sort()
	return out


func test_every_board_file_holds_the_medal_times_of_its_pilot_record() -> void:
	var record := _record()
	assert_false(record.is_empty(), "%s is there" % MedalRule.PILOT_RECORD)
	for path in _boards():
		var level := BoardLoader.load_board(path).level
		var entry: Dictionary = record.get(level.board_id, {})
		assert_false(entry.is_empty(), "%s: the pilot measured it" % path)
		if entry.is_empty():
			continue
		var text := FileAccess.get_file_as_string(path)
		assert_eq(
			entry["board"],
			MedalRule.fingerprint(text),
			"%s changed since the pilot measured it: run the pilot table with --write-medals" % path
		)
		var made := MedalRule.medal_times(
			float(entry["easy"]), PackedFloat64Array(entry["hard"]), not level.holes.is_empty()
		)
		assert_eq(level.medal_times_easy, made[0], "%s easy" % path)
		assert_eq(level.medal_times_hard, made[1], "%s hard" % path)
		if not level.holes.is_empty():
			assert_ne(level.medal_times_easy, level.medal_times_hard, "%s: holes cost time" % path)
		else:
			assert_eq(level.medal_times_easy, level.medal_times_hard, "%s: no holes" % path)


func test_the_record_is_what_the_pilot_plays() -> void:
	var level := BoardLoader.load_board(MAZE_DIR + "first_roll.board").level
	var entry: Dictionary = _record().get(level.board_id, {})
	var easy := MazeAutoplay.run(level, 120.0, 1, false)
	assert_true(easy["won"])
	assert_eq(MedalRule.rounded(easy["time_to_win"]), float(entry.get("easy", -1.0)))


func test_the_rule() -> void:
	var hard := PackedFloat64Array([30.0, 20.0, 40.0, 25.0, 50.0])
	var made := MedalRule.medal_times(22.0, hard, true)
	assert_eq(made[0], Medals.from_pilot_time(20.0), "easy: the fastest hard win was faster")
	assert_eq(made[1], Medals.from_pilot_time(30.0), "hard: the median hard win")
	made = MedalRule.medal_times(18.0, hard, false)
	assert_eq(made[1], made[0], "no holes: the same in both modes")
	made = MedalRule.medal_times(18.0, PackedFloat64Array(), true)
	assert_eq(made[1], Medals.from_pilot_time(18.0 * MedalRule.HARD_FALLBACK), "never won hard")


func test_easy_bronze_stays_in_reach_of_the_pilots_easy_game() -> void:
	# a lucky 10 s hard win would put bronze at 35 s, under the pilot's own 40 s easy game
	var made := MedalRule.medal_times(40.0, PackedFloat64Array([10.0, 30.0, 35.0]), true)
	assert_eq(made[0][0], Medals.from_pilot_time(10.0)[0], "gold from the fastest win")
	assert_eq(made[0][2], 40.0 * MedalRule.EASY_BRONZE_REACH, "bronze the easy game can reach")
	# and hard games all that fast would put hard bronze under easy's
	made = MedalRule.medal_times(40.0, PackedFloat64Array([10.0, 11.0, 12.0]), true)
	assert_eq(made[1][2], made[0][2] * MedalRule.HARD_MIN_SHARE, "hard bronze over easy's")
	made = MedalRule.medal_times(40.0, PackedFloat64Array([10.0, 20.0, 30.0]), true)
	assert_eq(made[1][0], Medals.from_pilot_time(20.0)[0], "hard gold from the median")
	made = MedalRule.medal_times(40.0, PackedFloat64Array([10.0]), false)
	assert_eq(made[1], made[0], "no holes: the same in both modes")


# Trial 6: Cloister's hard times were 0.2-0.4 s over easy's, Garden Path's bronze the same in
# both. On every board with holes each hard medal gives at least HARD_MIN_SHARE times easy's.
func test_hard_gives_clearly_more_time_wherever_there_are_holes() -> void:
	for path in _boards():
		var level := BoardLoader.load_board(path).level
		if level.holes.is_empty():
			continue
		for i in 3:
			var easy := level.medal_times_easy[i]
			var least := ceilf(easy * MedalRule.HARD_MIN_SHARE * 10.0) / 10.0
			assert_gte(
				level.medal_times_hard[i], least, "%s medal %d: %.1f s easy" % [path, i, easy]
			)
	var made := MedalRule.medal_times(20.0, PackedFloat64Array([20.0, 20.5, 21.0]), true)
	assert_eq(made[1][0], 36.0, "hard gold 1.2 x easy's 30 s, not the median's 30.8 s")


# Trial 7: most first finishes from board 3 on (30 to 50 s) earned nothing, and Cloister's
# bronze (47.5 s) was missed by 1.6 s after the route was worked out. Bronze is the reward
# for a first clean finish: silver 1.8 x gold, bronze 3.5 x gold.
func test_silver_and_bronze_are_a_first_timers_reach() -> void:
	var times := Medals.from_pilot_time(10.0)
	assert_almost_eq(times[1] / times[0], 1.8, 0.01, "silver is 1.8 x gold")
	assert_almost_eq(times[2] / times[0], 3.5, 0.01, "bronze is 3.5 x gold")
	var cloister := BoardLoader.load_board("res://levels/maze/cloister.board").level
	var bronze := Medals.times_for(cloister, false)[2]
	assert_gte(bronze, 49.1, "the trial's first Cloister finish earns bronze")
