extends GutTest
## Trial 9, complaint 2: "Too slow for a medal: finish anyway!" landed partway through a first
## run on a new board, "a downer on a first look". Before a board's first finish (in the mode
## played) the medal line says a first run is for finding the way in; once it has a best
## time, the medal chase's line comes back.

const TEST_SETTINGS := "user://test_maze_first_run_line_settings.cfg"
const TEST_SAVE := "user://test_maze_first_run_line_save.cfg"
const BOARD := "res://levels/maze/cloister.board"


func before_each() -> void:
	DirAccess.remove_absolute(ProjectSettings.globalize_path(TEST_SAVE))  # no best yet
	App.load_player_files(TEST_SETTINGS, TEST_SAVE)


func after_all() -> void:
	App.load_player_files(App.SETTINGS_PATH, App.SAVE_PATH)
	for path in [TEST_SETTINGS, TEST_SAVE]:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(path))


# The medal line for a run of `rules` at `seconds` on the clock.
func _line_at(rules: MazeRules, seconds: float) -> String:
	var labels: Array[Label] = []
	for i in 5:
		labels.append(autofree(Label.new()))
	var lines := MazeSideLines.new(labels[0], labels[1], labels[2], labels[3], labels[4])
	rules.elapsed = seconds
	lines.show_next_medal(rules)
	return lines.medal_line()


func test_a_first_run_past_bronze_is_encouraged_not_told_off() -> void:
	var rules := MazeRules.new(BoardLoader.load_board(BOARD).level)
	var bronze: float = Medals.times_for(rules.level, false)[2]
	assert_string_contains(_line_at(rules, 1.0), "Gold by", "the chase while gold is in reach")
	var line := _line_at(rules, bronze + 5.0)
	assert_eq(line, MazeSideLines.FIRST_RUN)
	assert_false(line.contains("Too slow"), "no telling off on a first run")


func test_once_the_board_has_a_best_the_chase_line_comes_back() -> void:
	var rules := MazeRules.new(BoardLoader.load_board(BOARD).level)
	var bronze: float = Medals.times_for(rules.level, false)[2]
	App.record_maze_time(rules.level.board_id, false, bronze + 20.0)
	assert_eq(_line_at(rules, bronze + 5.0), MazeSideLines.TOO_SLOW)
	rules.set_hard_mode(true)
	var hard_bronze: float = Medals.times_for(rules.level, true)[2]
	assert_eq(_line_at(rules, hard_bronze + 5.0), MazeSideLines.FIRST_RUN, "hard mode: a first run")
