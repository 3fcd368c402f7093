extends RefCounted
## The menu shots: the title screen, each game's level select, a card's menu and the My
## boards dialogs, the settings over the title screen (as its Settings button shows them),
## and the pause menu over a game.

const ShotCapture := preload("res://tools/shots/shot_capture.gd")
const ScreenOpener := preload("res://tools/shots/screen_opener.gd")
const MAIN_MENU := "res://scenes/menu/main_menu.tscn"
const LEVEL_SELECT := "res://scenes/menu/level_select.tscn"
const SETTINGS := "res://scenes/menu/settings_menu.tscn"
const PACHINKO := "res://scenes/pachinko/pachinko_game.tscn"
## The shots this file takes, in order.
const NAMES: Array[String] = [
	"menu_main",
	"menu_notice",
	"menu_level_select_pachinko",
	"menu_level_select_maze",
	"menu_my_boards",
	"menu_card_menu",
	"menu_export_dialog",
	"menu_delete_dialog",
	"menu_settings",
	"menu_pause",
]
## The problems the notice shot shows: as many lines as a badly damaged user folder gives.
const NOTICE_PROBLEMS: Array[String] = [
	"Settings: the file was damaged (line 3); kept as settings.cfg.bad-20261122-101500.",
	"Settings: master_volume (line 4) is not a number; using the default.",
	"Settings: pause had no key; Escape is bound again.",
	"Best results: the file is from a newer version of the game; it is left untouched and not saved.",
	"Best results: 2 records could not be read and were skipped.",
]
## The My boards shot's own scratch folder: the player's real boards never show in it.
const SHOT_BOARDS := "user://shots_boards"
## A file the loader refuses, shown greyed with its reason in the My boards shot.
const REFUSED_BOARD := "res://tests/fixtures/hostile_boards/pachinko/restitution_5.board"


## Opens the screen of `shot_name` and saves it. OK or the reason it failed.
static func take(tree: SceneTree, shot_name: String) -> Error:
	var screen: Node = null
	match shot_name:
		"menu_main":
			# The title screen focuses the game whose level select was seen last.
			App.level_select_kind = BoardLevel.PACHINKO_NAME
			screen = await ScreenOpener.open(tree, App.go_to_menu, MAIN_MENU)
		"menu_notice":
			# What a player sees after the game kept a damaged settings file aside.
			App.level_select_kind = BoardLevel.PACHINKO_NAME
			for problem: String in NOTICE_PROBLEMS:
				App.pending_problems.append(problem)
			screen = await ScreenOpener.open(tree, App.go_to_menu, MAIN_MENU)
		"menu_level_select_pachinko":
			screen = await ScreenOpener.open(
				tree, App.go_to_level_select.bind(BoardLevel.PACHINKO_NAME), LEVEL_SELECT
			)
		"menu_level_select_maze":
			_sample_progress()
			screen = await ScreenOpener.open(
				tree, App.go_to_level_select.bind(BoardLevel.MAZE_NAME), LEVEL_SELECT
			)
			if screen != null:
				await _wait_loaded(tree, screen as LevelSelect)
		"menu_my_boards":
			screen = await ScreenOpener.open(
				tree, App.go_to_level_select.bind(BoardLevel.PACHINKO_NAME), LEVEL_SELECT
			)
			if screen != null:
				await _show_my_boards(tree, screen as LevelSelect)
		"menu_card_menu":
			screen = await _level_select(tree, BoardLevel.PACHINKO_NAME)
			if screen != null:
				# on the second card, as the board_actions key (X / Square) opens it
				await _press(tree, &"ui_right")
				await _press(tree, &"board_actions")
		"menu_export_dialog":
			screen = await _level_select(tree, BoardLevel.PACHINKO_NAME)
			if screen != null:
				var dialogs: MyBoardsDialogs = screen.get_node("%Dialogs")
				dialogs.ask_export(str((screen as LevelSelect).first_card().get("board_path")))
		"menu_delete_dialog":
			screen = await ScreenOpener.open(
				tree, App.go_to_level_select.bind(BoardLevel.PACHINKO_NAME), LEVEL_SELECT
			)
			if screen != null:
				await _show_my_boards(tree, screen as LevelSelect)
				var slots := (screen as LevelSelect).my_slots()
				if not slots.is_empty():
					var dialogs: MyBoardsDialogs = screen.get_node("%Dialogs")
					var path := str(slots[0].card.get("board_path"))
					dialogs.ask_delete(path, slots[0].shown_name())
		"menu_pause":
			App.request_board(BoardLevel.PACHINKO_NAME, "res://levels/pachinko/classic.board")
			screen = await ScreenOpener.open(
				tree,
				App.start_game.bind(
					BoardLevel.PACHINKO_NAME, "res://levels/pachinko/classic.board"
				),
				PACHINKO
			)
			if screen != null:
				await _press(tree, &"pause")
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


static func _level_select(tree: SceneTree, game: String) -> LevelSelect:
	var screen := await ScreenOpener.open(tree, App.go_to_level_select.bind(game), LEVEL_SELECT)
	if screen != null:
		await _wait_loaded(tree, screen as LevelSelect)
	return screen as LevelSelect


# Presses and lets go of an input action, as a key or a pad button would.
static func _press(tree: SceneTree, action: StringName) -> void:
	for pressed: bool in [true, false]:
		var event := InputEventAction.new()
		event.action = action
		event.pressed = pressed
		Input.parse_input_event(event)
		await tree.process_frame
	await tree.process_frame


# A player one board in: medals on the first maze, the second open, the rest locked.
# The shot's save is in memory only (the player's own file is never touched).
static func _sample_progress() -> void:
	App.settings.unlock_all_boards = false
	var save: Object = load("res://scripts/app/save_data.gd").new()
	App.save_data = save
	var finishes := [["maze_garden", false, 0.95], ["maze_garden", true, 1.3]]
	for loaded in BoardLoader.list_boards(BoardLevel.Kind.MAZE):
		for finish: Array in finishes:
			if loaded.ok() and loaded.level.board_id == finish[0]:
				var hard: bool = finish[1]
				var times := Medals.times_for(loaded.level, hard)
				var share: float = finish[2]
				var seconds := times[0] * share if times.size() == 3 else 60.0
				save.call(&"record_maze_time", finish[0], hard, seconds)


# Waits until every card of the level select has loaded (their files load off the main thread).
static func _wait_loaded(tree: SceneTree, screen: LevelSelect) -> void:
	for frame in 240:
		if not screen.is_loading():
			break
		await tree.process_frame
	for frame in 3:
		await tree.process_frame


# Fills a scratch My boards folder (one imported board, one refused file), imports the
# board as the Import button would, and scrolls to the section.
static func _show_my_boards(tree: SceneTree, screen: LevelSelect) -> void:
	_empty_folder(SHOT_BOARDS + "/pachinko")
	DirAccess.make_dir_recursive_absolute(SHOT_BOARDS + "/pachinko")
	var refused := FileAccess.open(SHOT_BOARDS + "/pachinko/bouncy.board", FileAccess.WRITE)
	refused.store_buffer(FileAccess.get_file_as_bytes(REFUSED_BOARD))
	refused.close()
	screen.use_folder(SHOT_BOARDS)
	var source := ProjectSettings.globalize_path("res://levels/pachinko/windmills.board")
	screen.import_files(PackedStringArray([source]))
	for frame in 120:
		await tree.process_frame
		if not screen.is_loading():
			break
	var slots: Array = screen.my_slots()
	if not slots.is_empty():
		(slots[0].get("card") as Control).grab_focus()
	for frame in 10:
		await tree.process_frame
	# down to the end, so the cards' Export and Delete buttons show too
	var scroll := screen.get_node("%Scroll") as ScrollContainer
	scroll.scroll_vertical = int(scroll.get_v_scroll_bar().max_value)
	for frame in 3:
		await tree.process_frame


static func _empty_folder(folder: String) -> void:
	if DirAccess.dir_exists_absolute(folder):
		for file_name in DirAccess.get_files_at(folder):
			DirAccess.remove_absolute(folder.path_join(file_name))
