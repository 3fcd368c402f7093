extends GutTest
## The App autoload's own logic, on a fresh instance (never the live autoload): a damaged
## settings file is reported once and replaced, best results are kept per board, and the
## board a game plays comes from the play-test request, the level select, or the default.

const AppScript := preload("res://scenes/app/app.gd")
const SETTINGS := "user://test_app_settings.cfg"
const SAVE := "user://test_app_save.cfg"

var _app: AppScript


func before_each() -> void:
	_app = AppScript.new()
	DirAccess.remove_absolute(PlaytestRequest.PATH)


func after_each() -> void:
	_app.free()
	for path: String in [SETTINGS, SAVE, PlaytestRequest.PATH]:
		DirAccess.remove_absolute(path)
	for name in DirAccess.get_files_at("user://"):
		if name.begins_with("test_app_") and name.contains(".cfg.bad-"):
			DirAccess.remove_absolute("user://" + name)  # the damaged files App kept aside
	GameSettings.new().apply()


func _write(path: String, text: String) -> void:
	var file := FileAccess.open(path, FileAccess.WRITE)
	file.store_string(text)
	file.close()


func test_damaged_settings_are_reported_once_and_replaced() -> void:
	_write(SETTINGS, "this is not a settings file {{{")
	_app.load_player_files(SETTINGS, SAVE)
	var problems: PackedStringArray = _app.take_problems()
	assert_eq(problems.size(), 1)
	assert_string_contains(problems[0], ProjectSettings.globalize_path(SETTINGS))
	assert_eq((_app.take_problems() as PackedStringArray).size(), 0, "handed out once")
	var again := AppScript.new()
	again.load_player_files(SETTINGS, SAVE)
	assert_eq((again.take_problems() as PackedStringArray).size(), 0, "file was replaced")
	again.free()


func test_default_board_is_the_classic_one() -> void:
	assert_eq(_app.current_board_path("maze"), "res://levels/maze/classic.board")
	assert_eq(_app.current_board_path("pachinko"), "res://levels/pachinko/classic.board")


func test_requested_board_is_used() -> void:
	_app.request_board("maze", "res://levels/maze/other.board")
	assert_eq(_app.current_board_path("maze"), "res://levels/maze/other.board")
	assert_eq(_app.current_board_path("pachinko"), "res://levels/pachinko/classic.board")


func test_playtest_request_wins_once_and_stays_for_restarts() -> void:
	_app.request_board("pachinko", "res://levels/pachinko/picked.board")
	assert_eq(PlaytestRequest.write("res://levels/pachinko/draft.board", "pachinko"), "")
	assert_eq(_app.current_board_path("pachinko"), "res://levels/pachinko/draft.board")
	assert_false(FileAccess.file_exists(PlaytestRequest.PATH), "request consumed")
	assert_eq(_app.current_board_path("pachinko"), "res://levels/pachinko/draft.board")


func test_playtest_request_for_the_other_game_is_left_alone() -> void:
	assert_eq(PlaytestRequest.write("res://levels/maze/draft.board", "maze"), "")
	assert_eq(_app.current_board_path("pachinko"), "res://levels/pachinko/classic.board")
	assert_eq(_app.current_board_path("maze"), "res://levels/maze/draft.board")


func test_best_maze_time_keeps_the_fastest_and_persists() -> void:
	_app.load_player_files(SETTINGS, SAVE)
	assert_eq(_app.best_maze_time("classic", false), -1.0)
	assert_true(_app.record_maze_time("classic", false, 42.5))
	assert_false(_app.record_maze_time("classic", false, 50.0))
	assert_true(_app.record_maze_time("classic", false, 30.25))
	var again := AppScript.new()
	again.load_player_files(SETTINGS, SAVE)
	assert_eq(again.best_maze_time("classic", false), 30.25)
	assert_eq(again.best_maze_time("other", false), -1.0)
	again.free()


func test_best_pachinko_balls_keeps_the_most_and_persists() -> void:
	_app.load_player_files(SETTINGS, SAVE)
	assert_eq(_app.best_pachinko_balls("classic"), -1)
	assert_false(_app.record_pachinko_balls("classic", 12), "a first game is no new best")
	assert_eq(_app.best_pachinko_balls("classic"), 12, "but it is the record")
	assert_false(_app.record_pachinko_balls("classic", 12))
	assert_true(_app.record_pachinko_balls("classic", 20))
	var again := AppScript.new()
	again.load_player_files(SETTINGS, SAVE)
	assert_eq(again.best_pachinko_balls("classic"), 20)
	again.free()


func test_nonsense_results_are_refused() -> void:
	_app.load_player_files(SETTINGS, SAVE)
	assert_false(_app.record_maze_time("classic", false, -3.0))
	assert_false(_app.record_maze_time("classic", false, NAN))
	assert_false(_app.record_pachinko_balls("", 5))
	assert_push_error_count(3)
	assert_eq(_app.best_maze_time("classic", false), -1.0)


func test_damaged_save_file_is_reported_and_records_start_empty() -> void:
	_write(SAVE, "[maze_best_seconds\nclassic=oops")
	_app.load_player_files(SETTINGS, SAVE)
	var problems: PackedStringArray = _app.take_problems()
	assert_eq(problems.size(), 1)
	assert_string_contains(problems[0], ProjectSettings.globalize_path(SAVE))
	assert_eq(_app.best_maze_time("classic", false), -1.0)
