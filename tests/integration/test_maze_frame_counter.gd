extends GutTest
## The maze's frame counter keeps clear of the board's title (a play trial turned it on in a
## 1201 x 676 window and it covered the title).

const GAME := preload("res://scenes/maze/maze_game.tscn")
const StretchedWindow := preload("res://tests/integration/stretched_window.gd")
const TEST_SETTINGS := "user://test_maze_frame_counter_settings.cfg"
const TEST_SAVE := "user://test_maze_frame_counter_save.cfg"


func before_all() -> void:
	App.load_player_files(TEST_SETTINGS, TEST_SAVE)


func after_all() -> void:
	App.load_player_files(App.SETTINGS_PATH, App.SAVE_PATH)
	for path in [TEST_SETTINGS, TEST_SAVE]:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(path))


# A play trial turned the frame counter on (F) in a 1201 x 676 window: it covered the
# board's title.
func test_the_frame_counter_leaves_the_title_clear() -> void:
	App.settings.set_value("show_frame_counter", true)
	var game := await StretchedWindow.open(self, GAME, Vector2i(1201, 676), 2) as MazeGame
	await wait_seconds(0.4)  # the counter shows its first figure
	App.settings.set_value("show_frame_counter", false)
	var title := game.get_node("Side/Title") as Control
	var counter := game.find_child("FpsLabel", true, false) as Control
	assert_not_null(counter, "the counter is on the maze screen")
	var title_rect := title.get_global_rect()
	var counter_rect := counter.get_global_rect()
	assert_false(
		title_rect.intersects(counter_rect), "title %s, counter %s" % [title_rect, counter_rect]
	)
