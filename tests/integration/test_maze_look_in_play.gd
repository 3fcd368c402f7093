extends GutTest
## The board style in Settings (wood and steel, or the tutorial's flat look) shows at once
## on the board in play, as Low graphics does: trial 7 switched it from the pause menu and
## the board stayed wood, even after a restart, until it was opened again.

const GAME := preload("res://scenes/maze/maze_game.tscn")
const TEST_SETTINGS := "user://test_maze_look_in_play_settings.cfg"
const TEST_SAVE := "user://test_maze_look_in_play_save.cfg"

var _game: MazeGame


func before_all() -> void:
	App.load_player_files(TEST_SETTINGS, TEST_SAVE)


func after_all() -> void:
	App.settings.set_value("maze_tutorial_look", false)
	App.load_player_files(App.SETTINGS_PATH, App.SAVE_PATH)
	for path in [TEST_SETTINGS, TEST_SAVE]:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(path))


func before_each() -> void:
	App.settings.set_value("maze_tutorial_look", false)
	_game = GAME.instantiate()
	add_child_autofree(_game)
	await wait_process_frames(2)


func _floor_colour() -> Color:
	return _game.stage().board().floor_material().get_shader_parameter("floor_color")


func test_the_tutorial_look_shows_at_once_and_wood_comes_back() -> void:
	assert_eq(_floor_colour(), MazeBoard3d.MAPLE, "wood to begin with")
	var steel: Material = _game.stage().balls().material
	App.settings.set_value("maze_tutorial_look", true)
	App.settings.changed.emit()
	assert_true(_game.stage().tutorial_look)
	assert_eq(_floor_colour(), MazePalette.BACKGROUND, "the flat floor on the board in play")
	assert_ne(_game.stage().balls().material, steel, "red balls, not steel")
	App.settings.set_value("maze_tutorial_look", false)
	App.settings.changed.emit()
	assert_eq(_floor_colour(), MazeBoard3d.MAPLE, "wood again")
