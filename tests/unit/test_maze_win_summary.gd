extends GutTest
## What a maze win says (MazeWinSummary) and the medal still in reach while playing
## (Medals.next_target): the medal earned or how far from the next, and the best-time change.

const TIMES := [30.0, 45.0, 70.0]


func _level() -> BoardLevel:
	var level := BoardLevel.new()
	level.kind = BoardLevel.Kind.MAZE
	level.medal_times_easy = PackedFloat64Array(TIMES)
	level.medal_times_hard = PackedFloat64Array([40.0, 60.0, 90.0])
	return level


func test_next_target_is_the_best_medal_still_in_reach() -> void:
	var times := PackedFloat64Array(TIMES)
	assert_eq(Medals.next_target(times, 0.0), {"medal": Medals.Medal.GOLD, "seconds": 30.0})
	assert_eq(Medals.next_target(times, 30.0)["medal"], Medals.Medal.GOLD, "30.0 still gold")
	assert_eq(Medals.next_target(times, 30.1), {"medal": Medals.Medal.SILVER, "seconds": 45.0})
	assert_eq(Medals.next_target(times, 50.0), {"medal": Medals.Medal.BRONZE, "seconds": 70.0})
	assert_eq(Medals.next_target(times, 70.5)["medal"], Medals.Medal.NONE, "all passed")
	assert_eq(Medals.next_target(PackedFloat64Array(), 1.0)["medal"], Medals.Medal.NONE)


func test_a_gold_win_says_gold_and_the_best_it_beat() -> void:
	var summary := MazeWinSummary.of(_level(), false, 28.0, 31.5)
	assert_eq(summary.medal, Medals.Medal.GOLD)
	assert_eq(summary.headline(), "Gold!")
	assert_eq(summary.medal_line(), "", "the title says the medal once")
	assert_true(summary.new_best)
	assert_eq(summary.best_line(), "New best: 3.5 s faster than before")


func test_a_silver_win_says_how_far_from_gold() -> void:
	var summary := MazeWinSummary.of(_level(), false, 31.8, 29.0)
	assert_eq(summary.medal, Medals.Medal.SILVER)
	assert_eq(summary.next_medal, Medals.Medal.GOLD)
	assert_eq(summary.headline(), "Silver!")
	assert_eq(summary.medal_line(), "1.8 s short of Gold", "the medal not said twice")
	assert_false(summary.new_best)
	assert_eq(summary.best_line(), "2.8 s slower than your best (0:29.0)")


func test_a_win_the_clock_shows_at_the_gold_time_is_gold_and_the_live_target_agrees() -> void:
	var level := _level()
	level.medal_times_easy = PackedFloat64Array([22.8, 45.0, 70.0])
	var summary := MazeWinSummary.of(level, false, 22.833, -1.0)
	assert_eq(MazeWinSummary.clock(22.833), "0:22.8")
	assert_eq(summary.headline(), "Gold!", "as the clock reads, not 0.1 s short")
	var times := level.medal_times_easy
	assert_eq(Medals.next_target(times, 22.85)["medal"], Medals.Medal.GOLD, "still 0:22.8")
	var late := MazeWinSummary.of(level, false, 22.95, -1.0)
	assert_eq(late.medal_line(), "0.1 s short of Gold", "0:22.9 against 0:22.8")


func test_no_medal_says_how_far_from_bronze_and_hard_uses_its_own_times() -> void:
	var summary := MazeWinSummary.of(_level(), true, 94.0, -1.0)
	assert_eq(summary.medal, Medals.Medal.NONE)
	assert_eq(summary.headline(), "Finished!")
	assert_eq(summary.medal_line(), "Bronze is under 1:30.0", "kind: the target, not the gap")
	assert_true(summary.new_best, "a first finish is the best")
	assert_eq(summary.best_line(), "Your first finish: that's your best time")


func test_a_board_without_medal_times_says_nothing_about_medals() -> void:
	var level := BoardLevel.new()
	level.kind = BoardLevel.Kind.MAZE
	assert_eq(MazeWinSummary.of(level, false, 12.0, -1.0).medal_line(), "")


func test_clock_shows_minutes_seconds_and_tenths() -> void:
	assert_eq(MazeWinSummary.clock(84.7), "1:24.7")
	assert_eq(MazeWinSummary.clock(5.0), "0:05.0")
	assert_eq(MazeWinSummary.clock(600.05), "10:00.0")


func test_the_next_board_follows_the_opening_order() -> void:
	assert_eq(MazeProgress.next_of("maze_first_roll"), "maze_two_together")
	assert_eq(MazeProgress.next_of("maze_garden"), "maze_switchbacks")
	assert_eq(MazeProgress.next_of("maze_undercroft"), "", "the last has none")
	assert_eq(MazeProgress.next_of("my:garden.board"), "", "a board of your own has none")
	for id in MazeProgress.ORDER:
		assert_true(FileAccess.file_exists(MazeProgress.shipped_path(id)), id)
