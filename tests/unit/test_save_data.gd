extends GutTest
## Best results: the maze keeps one best time per board and mode (easy and hard never share
## one), version 1 files migrate with their times as easy times, pachinko keeps the most balls.

const PATH := "user://test_save_data.cfg"


func after_each() -> void:
	DirAccess.remove_absolute(PATH)


func _write(text: String) -> void:
	var file := FileAccess.open(PATH, FileAccess.WRITE)
	file.store_string(text)
	file.close()


func _loaded() -> SaveData:
	var data := SaveData.new()
	assert_eq(data.load_file(PATH), "", "loads without a problem")
	return data


func test_easy_and_hard_keep_their_own_best_time() -> void:
	var data := _loaded()
	assert_true(data.record_maze_time("classic", false, 40.0))
	assert_true(data.record_maze_time("classic", true, 55.0), "a slower hard run is a hard best")
	assert_true(data.record_maze_time("classic", true, 50.0))
	assert_false(data.record_maze_time("classic", false, 45.0))
	assert_eq(data.best_maze_time("classic", false), 40.0)
	assert_eq(data.best_maze_time("classic", true), 50.0)


func test_both_modes_survive_a_reload() -> void:
	var data := _loaded()
	data.record_maze_time("classic", false, 40.0)
	data.record_maze_time("classic", true, 65.5)
	data.record_pachinko_balls("classic", 12)
	var again := _loaded()
	assert_eq(again.best_maze_time("classic", false), 40.0)
	assert_eq(again.best_maze_time("classic", true), 65.5)
	assert_eq(again.best_pachinko_balls("classic"), 12)
	assert_eq(again.best_maze_time("other", true), -1.0)


func test_a_version_1_file_migrates_its_times_as_easy() -> void:
	_write(
		"[meta]\nversion=1\n\n[maze_best_seconds]\nclassic=33.5\n\n[pachinko_best_balls]\nclassic=7\n"
	)
	var data := _loaded()
	assert_eq(data.best_maze_time("classic", false), 33.5)
	assert_eq(data.best_maze_time("classic", true), -1.0, "version 1 never told the modes apart")
	assert_eq(data.best_pachinko_balls("classic"), -1, "balls paid back are no 'most won'")
	data.record_maze_time("classic", true, 80.0)
	var text := FileAccess.get_file_as_string(PATH)
	assert_string_contains(text, "version=%d" % SaveData.VERSION)
	var again := _loaded()
	assert_eq(again.best_maze_time("classic", false), 33.5, "the migrated time is kept")
	assert_eq(again.best_maze_time("classic", true), 80.0)


func test_new_best_pachinko_only_when_a_game_beats_an_earlier_one() -> void:
	var data := _loaded()
	assert_false(data.record_pachinko_balls("fever", 0), "nothing won is never a new best")
	assert_eq(data.best_pachinko_balls("fever"), 0, "but the first game is on the record")
	assert_false(data.record_pachinko_balls("fever", 0), "nor is nothing won again")
	assert_true(data.record_pachinko_balls("fever", 9), "9 balls beat 0")
	assert_false(data.record_pachinko_balls("fever", 9), "a tie is no new best")
	assert_false(data.record_pachinko_balls("fever", 4))
	assert_eq(data.best_pachinko_balls("fever"), 9)
	assert_false(data.record_pachinko_balls("hanami", 120), "a first game on a board sets it")
	assert_true(data.record_pachinko_balls("hanami", 121))


# [pachinko_best_balls] held balls PAID BACK before the best became the most balls won: an
# old record is kept in the file as it was, but never shown (or beaten) as "Most won".
func test_an_old_paid_back_record_is_kept_but_not_shown_as_most_won() -> void:
	_write("[meta]\nversion=2\n\n[pachinko_best_balls]\npachinko_fever=500\n")
	var data := _loaded()
	assert_eq(data.best_pachinko_balls("pachinko_fever"), -1, "500 paid back is not 500 won")
	assert_false(data.record_pachinko_balls("pachinko_fever", 30), "a first game sets it")
	assert_eq(data.best_pachinko_balls("pachinko_fever"), 30)
	var text := FileAccess.get_file_as_string(PATH)
	assert_string_contains(text, "[pachinko_best_balls]\npachinko_fever=500", "kept untouched")
	assert_string_contains(text, "[pachinko_most_won]\npachinko_fever=30")
	var again := _loaded()
	assert_eq(again.best_pachinko_balls("pachinko_fever"), 30)


# The full pachinko rules card comes once per board: which boards' cards were played past
# is kept in the file, and a line that is not a plain yes is left out without a problem.
func test_the_rules_cards_seen_survive_a_reload() -> void:
	var data := _loaded()
	assert_false(data.has_seen_pachinko_rules("pachinko_fever"))
	data.note_pachinko_rules_seen("pachinko_fever")
	var again := _loaded()
	assert_true(again.has_seen_pachinko_rules("pachinko_fever"))
	assert_false(again.has_seen_pachinko_rules("pachinko_hanami"))
	_write(
		'[meta]\nversion=2\n\n[pachinko_rules_seen]\npachinko_fever=true\npachinko_hanami="maybe"\n'
	)
	var read := _loaded()
	assert_true(read.has_seen_pachinko_rules("pachinko_fever"))
	assert_false(read.has_seen_pachinko_rules("pachinko_hanami"))
