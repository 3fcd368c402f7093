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


# A play trial at 10 FPS: "10 FPS  100.0 ms" grew the panel past the window's left edge.
func test_the_counter_keeps_its_place_and_margin_at_any_figure() -> void:
	App.settings.set_value("show_frame_counter", true)  # a hidden label keeps its old size
	for bottom_left in [true, false]:
		var counter := (load("res://scenes/common/frame_counter.tscn") as PackedScene).instantiate()
		counter.set("bottom_left", bottom_left)
		add_child_autofree(counter)
		var label := counter.get_node("%FpsLabel") as Label
		var view := label.get_viewport_rect()
		var rects: Array[Rect2] = []
		for figure in [
			"60 FPS  16.7 ms", "10 FPS  100.0 ms", "1 FPS  1000.0 ms", "888 FPS  1.1 ms"
		]:
			label.text = figure
			await wait_process_frames(2)
			var rect := label.get_global_rect()
			rects.append(rect)
			assert_gte(rect.position.x, 8.0, "%s: left margin kept (%s)" % [figure, rect])
			assert_lte(rect.end.x, view.end.x - 8.0, "%s: right margin kept (%s)" % [figure, rect])
		for rect in rects:
			assert_eq(rect, rects[0], "the panel does not move or grow as the figure changes")
	App.settings.set_value("show_frame_counter", false)
