extends RefCounted
## The menu shots: the title screen, each game's level select, and the settings over the
## title screen (as its Settings button shows them).

const ShotCapture := preload("res://tools/shots/shot_capture.gd")
const ScreenOpener := preload("res://tools/shots/screen_opener.gd")
const MAIN_MENU := "res://scenes/menu/main_menu.tscn"
const LEVEL_SELECT := "res://scenes/menu/level_select.tscn"
const SETTINGS := "res://scenes/menu/settings_menu.tscn"
## The shots this file takes, in order.
const NAMES: Array[String] = [
	"menu_main", "menu_level_select_pachinko", "menu_level_select_maze", "menu_settings"
]


## Opens the screen of `shot_name` and saves it. OK or the reason it failed.
static func take(tree: SceneTree, shot_name: String) -> Error:
	var screen: Node = null
	match shot_name:
		"menu_main":
			# The title screen focuses the game whose level select was seen last.
			App.level_select_kind = "pachinko"
			screen = await ScreenOpener.open(tree, App.go_to_menu, MAIN_MENU)
		"menu_level_select_pachinko":
			screen = await ScreenOpener.open(
				tree, App.go_to_level_select.bind("pachinko"), LEVEL_SELECT
			)
		"menu_level_select_maze":
			_sample_progress()
			screen = await ScreenOpener.open(
				tree, App.go_to_level_select.bind("maze"), LEVEL_SELECT
			)
		"menu_settings":
			screen = await ScreenOpener.open(tree, App.go_to_menu, MAIN_MENU)
			if screen != null:
				# The settings scene is an overlay the title screen adds as its own child.
				var settings: PackedScene = load(SETTINGS)
				screen.add_child(settings.instantiate())
		_:
			printerr("shots: menu_shots has no shot '%s'" % shot_name)
			return ERR_INVALID_PARAMETER
	if screen == null:
		return ERR_CANT_OPEN
	return await ShotCapture.save(tree.root, ShotCapture.path_for(shot_name))


# A player two boards in: medals on the first two mazes, the third open, the rest locked.
# The shot's save is in memory only (the player's own file is never touched).
static func _sample_progress() -> void:
	App.settings.unlock_all_boards = false
	var save: Object = load("res://scripts/app/save_data.gd").new()
	App.save_data = save
	var finishes := [["maze_garden", false, 0.95], ["maze_garden", true, 1.3]]
	finishes += [["maze_classic", false, 1.8]]
	for loaded in BoardLoader.list_boards(BoardLevel.Kind.MAZE):
		for finish: Array in finishes:
			if loaded.ok() and loaded.level.board_id == finish[0]:
				var hard: bool = finish[1]
				var times := Medals.times_for(loaded.level, hard)
				var share: float = finish[2]
				var seconds := times[0] * share if times.size() == 3 else 60.0
				# per board and mode when the save has modes, else per board
				if save.get_method_argument_count(&"record_maze_time") >= 3:
					save.call(&"record_maze_time", finish[0], hard, seconds)
				elif not hard:
					save.call(&"record_maze_time", finish[0], seconds)
