extends GutTest
## A maze board opens ready: a play trial's first frame of a board showed no balls and the
## scene's placeholder "Gold by 0:00.0" until the next frame.

const GAME := preload("res://scenes/maze/maze_game.tscn")
const TEST_SETTINGS := "user://test_maze_opening_settings.cfg"
const TEST_SAVE := "user://test_maze_opening_save.cfg"


func before_all() -> void:
	App.load_player_files(TEST_SETTINGS, TEST_SAVE)


func after_all() -> void:
	App.load_player_files(App.SETTINGS_PATH, App.SAVE_PATH)
	for path in [TEST_SETTINGS, TEST_SAVE]:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(path))


func test_the_board_opens_with_its_balls_and_medal_target_before_any_frame() -> void:
	var game: MazeGame = GAME.instantiate()
	add_child_autofree(game)
	var rules := game.rules
	assert_eq(game.stage().balls().get_child_count(), rules.ball_total(), "every ball is drawn")
	var label: Label = game.get_node("%NextMedal")
	var gold: float = rules.level.medal_times_easy[0]
	assert_eq(label.text, "Gold by %s" % MazeWinSummary.clock(gold))
