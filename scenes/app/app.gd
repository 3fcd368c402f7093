extends Node
## The one autoload. Hands the command-line flags to command_line.gd, which may run a
## command or refuse bad flags, and then quits; otherwise holds the player's settings and best
## results, the board each game should play, and the scene changes between menus and games.

## Emitted once for each problem with the settings or best-results file (the sentence names
## the file, what was wrong, and where a damaged file was kept).
signal problem_reported(message: String)

const SETTINGS_PATH := "user://settings.cfg"
const SAVE_PATH := "user://save.cfg"
## Frames a scene change may take before the curtain comes down anyway.
const SCENE_CHANGE_FRAMES := 30
const MENU_SCENE := "res://scenes/menu/main_menu.tscn"
const LEVEL_SELECT_SCENE := "res://scenes/menu/level_select.tscn"
const GAME_SCENES := {
	BoardLevel.PACHINKO_NAME: "res://scenes/pachinko/pachinko_game.tscn",
	BoardLevel.MAZE_NAME: "res://scenes/maze/maze_game.tscn",
}

## The player's settings (volumes, window, frame counter, tilt sensitivity, bindings).
var settings := GameSettings.new()
## Best results per board.
var save_data := SaveData.new()
## Which game the level select lists (a name of BoardLevel.KIND_NAMES).
var level_select_kind := BoardLevel.PACHINKO_NAME
## Whether a pachinko board the player has played from its full rules card opens with a
## one-line reminder instead (the game does; tool scripts, tests and pictures among them,
## start with it off so each opens on the full card whatever the user folder holds).
var skip_seen_rules_cards := true
## Whether a new player's first start-pocket hit on a reel machine lands the house's jackpot
## (HouseJackpot; the game does; tool scripts and tests start with it off, so their games
## spin as the seed says whatever the user folder holds, and a test turns it on to check it).
var house_jackpots := true
## True when the player last chose hard mode (H) on a maze board with black holes, false
## once they choose easy (E): every board with holes opens in that mode, whether through Next
## board or the board list (trial 9 pressed H on every board; trial 10 was dropped back into
## easy through "Other boards" after a hard run, while Next board kept hard).
var maze_hard_chosen := false
## Problems found while loading the player's files, not yet shown to the player.
var pending_problems := PackedStringArray()

## Up from the moment a scene change is asked for until the new screen has drawn.
var curtain := LoadingCurtain.new()

var _picked_boards := {}
# scene changes asked for so far: only the latest one lowers the curtain
var _changes := 0
# scenes being loaded on a worker (ResourceLoader's threaded load), by path
var _background_loads := {}
var _settings_path := SETTINGS_PATH
# the window size set at start (WindowFit), ZERO when the window was left alone
var _fitted_window_size := Vector2i.ZERO


func _init() -> void:
	# first of all, so the log holds everything the game says (GameLogFile says why it is ours)
	var log_file := GameLogFile.new()
	if log_file.is_open():
		OS.add_logger(log_file)


func _ready() -> void:
	curtain.name = "LoadingCurtain"
	add_child(curtain)
	# A tool script run with -s (converters, shots, tests) owns the arguments after `--`.
	var engine_args := OS.get_cmdline_args()
	# The GUT suites on the release template run as the test pack's main scene, not with -s:
	# they too always get the full rules card, whatever boards an earlier test marked seen.
	if OS.has_feature("release_tests"):
		skip_seen_rules_cards = false
		house_jackpots = false
	if engine_args.has("-s") or engine_args.has("--script"):
		skip_seen_rules_cards = false
		house_jackpots = false
		load_player_files(SETTINGS_PATH, SAVE_PATH)
		return
	var code := CommandLine.run(OS.get_cmdline_user_args())
	if code != CommandLine.START_GAME:
		get_tree().quit(code)
		return
	load_player_files(SETTINGS_PATH, SAVE_PATH)
	_fitted_window_size = WindowFit.fit_window(get_window(), settings.window_size)
	# the sounds build on a worker while the player reads the menu, not when a board loads
	# (and not while the menu itself loads: after its first frame)
	# (headless there is nothing to hear: the worker would only cost CPU, and Debian's release
	# template crashed at exit after it in the headless test run)
	if DisplayServer.get_name() != "headless":
		RenderingServer.frame_post_draw.connect(
			func() -> void: SoundBank.warm_in_background(SoundRecipes.names()), CONNECT_ONE_SHOT
		)


# The game is quitting (App leaves the tree last, after the scenes that cancelled their
# board loadings): wait for those loading threads, so none is destroyed while it runs.
func _exit_tree() -> void:
	_remember_window_size()
	BoardListLoading.wait_for_cancelled()
	SoundBank.wait_for_background()
	MusicBank.wait_for_background()
	# a game scene loaded for a board never chosen: take it, so it is freed with the rest
	for path: String in _background_loads:
		ResourceLoader.load_threaded_get(path)
	_background_loads.clear()


## Loads settings and best results and applies the settings. After a problem the file is
## written again right away (a damaged one was moved aside first, so nothing is lost), so the
## problem is reported once, not on every start; a newer version's file is never written.
func load_player_files(settings_path: String, save_path: String) -> void:
	_settings_path = settings_path
	var problem := settings.load_file(settings_path)
	if not problem.is_empty():
		_report(problem)
		settings.save_file(settings_path)
	settings.apply()
	var save_problem := save_data.load_file(save_path)
	if not save_problem.is_empty():
		_report(save_problem)
		save_data.save()


## Applies the current settings and writes them to the settings file.
func save_settings() -> void:
	settings.apply()
	settings.save_file(_settings_path)


## Takes the problems not yet shown to the player (each is handed out once).
func take_problems() -> PackedStringArray:
	var problems := pending_problems
	pending_problems = PackedStringArray()
	return problems


## Remembers the board the player picked for a game; call before changing scene.
func request_board(kind: String, path: String) -> void:
	if not GAME_SCENES.has(kind):
		push_error("App.request_board: unknown game kind '%s'" % kind)
		return
	_picked_boards[kind] = path


## The board a game scene should load: an editor play-test request first (consumed once,
## then kept for restarts), then the level select's pick, else the classic board.
func current_board_path(kind: String) -> String:
	var requested := PlaytestRequest.take(kind)
	if not requested.is_empty():
		_picked_boards[kind] = requested
		return requested
	if _picked_boards.has(kind):
		return _picked_boards[kind]
	return "res://levels/%s/classic.board" % kind


## Best maze time on a board in one mode (`hard` or easy) in seconds, -1 when none.
func best_maze_time(board_id: String, hard: bool) -> float:
	return save_data.best_maze_time(board_id, hard)


## Records a finished maze run in one mode; true when it is a new best for that mode.
func record_maze_time(board_id: String, hard: bool, seconds: float) -> bool:
	return save_data.record_maze_time(board_id, hard, seconds)


## Most pachinko balls won on a board, -1 when none.
func best_pachinko_balls(board_id: String) -> int:
	return save_data.best_pachinko_balls(board_id)


## Records a finished pachinko game; true when it is a new best.
func record_pachinko_balls(board_id: String, balls: int) -> bool:
	return save_data.record_pachinko_balls(board_id, balls)


## True when a game on `board_id` opens with the one-line reminder, not the full rules card:
## the player has played it from the full card before (SaveData).
func skips_rules_card(board_id: String) -> bool:
	return skip_seen_rules_cards and save_data.has_seen_pachinko_rules(board_id)


## Remembers that the player played `board_id` from its full rules card.
func note_pachinko_rules_seen(board_id: String) -> void:
	save_data.note_pachinko_rules_seen(board_id)


## True once the player has filled `board_id`'s tray to its goal (PachinkoGoals).
func has_cleared_pachinko(board_id: String) -> bool:
	return save_data.has_cleared_pachinko(board_id)


## Remembers that the player cleared `board_id`.
func note_pachinko_cleared(board_id: String) -> void:
	save_data.note_pachinko_cleared(board_id)


## The pachinko handle's strength the player left it at (LaunchHandle.DEFAULT_POWER before
## they ever turned it): kept across boards and games.
func pachinko_handle_power() -> float:
	var kept := save_data.pachinko_handle_power()
	return kept if kept >= 0.0 else LaunchHandle.DEFAULT_POWER


## Keeps the pachinko handle's strength for the next game and board.
func keep_pachinko_handle_power(power: float) -> void:
	save_data.keep_pachinko_handle_power(power)


## The board last picked for a game of `kind` this run (the level select's focus goes back to
## it), "" when none was.
func last_board_path(kind: String) -> String:
	var path: String = _picked_boards.get(kind, "")
	return path


## Leaves whatever is running (unpausing it) for the main menu.
func go_to_menu() -> void:
	_change_scene(MENU_SCENE)


## Opens the level select listing the boards of one game.
func go_to_level_select(kind: String) -> void:
	level_select_kind = kind
	await _change_scene(LEVEL_SELECT_SCENE)
	# the game's scene (0.8 s of loading and compiling) loads on a worker while the player
	# picks a board, once the level select is up (it loads its own boards meanwhile)
	if GAME_SCENES.has(kind):
		var game_scene: String = GAME_SCENES[kind]
		_load_in_background(game_scene)


## Starts loading the game scene of `kind` on a worker (the title does for Play Pachinko,
## so the board is up sooner after the press); start_game takes it from there.
func preload_game(kind: String) -> void:
	if GAME_SCENES.has(kind):
		var scene_path: String = GAME_SCENES[kind]
		_load_in_background(scene_path)


## Starts a game on a board.
func start_game(kind: String, path: String) -> void:
	if not GAME_SCENES.has(kind):
		push_error("App.start_game: unknown game kind '%s'" % kind)
		return
	request_board(kind, path)
	level_select_kind = kind  # the list the pause menu's "Other boards" goes back to
	var scene_path: String = GAME_SCENES[kind]
	_change_scene(scene_path)


# The curtain goes up first and is drawn before the wait begins (a board took seconds to
# load with nothing on the screen); it comes down with the new screen's first frame.
func _change_scene(path: String) -> void:
	get_tree().paused = false
	_changes += 1
	var change := _changes
	curtain.cover()
	# the scene loads on a worker while the curtain is drawn (not one after the other); the
	# change waits for at least one drawn frame, so the curtain is up before the new screen's
	# own setup holds the main thread
	_load_in_background(path)
	var drawing := DisplayServer.get_name() != "headless"
	await (RenderingServer.frame_post_draw if drawing else get_tree().process_frame)
	while (
		_background_loads.has(path)
		and ResourceLoader.load_threaded_get_status(path) == ResourceLoader.THREAD_LOAD_IN_PROGRESS
	):
		await get_tree().process_frame
	if change != _changes:
		return  # a later change owns the screen now
	var leaving := get_tree().current_scene
	var error: Error
	if _background_loads.has(path):
		_background_loads.erase(path)
		var scene := ResourceLoader.load_threaded_get(path) as PackedScene
		error = get_tree().change_scene_to_packed(scene) if scene != null else ERR_CANT_OPEN
	else:
		error = get_tree().change_scene_to_file(path)
	if error != OK:
		push_error("Could not open the scene %s: %s" % [path, error_string(error)])
		curtain.lift()
		return
	# lowered the moment the new screen is in the tree, so that screen's first frame is drawn
	# without it (the curtain stays on the screen until then); the frames below are a net
	get_tree().scene_changed.connect(
		func() -> void:
			if change == _changes:
				curtain.lift(),
		CONNECT_ONE_SHOT
	)
	for frame in SCENE_CHANGE_FRAMES:
		await get_tree().process_frame
		var now := get_tree().current_scene
		if now != null and now != leaving:
			break
	if change == _changes:
		curtain.lift()


# Starts loading the scene at `path` on a worker, once; _change_scene takes it from there.
func _load_in_background(path: String) -> void:
	if _background_loads.has(path):
		return
	if ResourceLoader.load_threaded_request(path, "PackedScene") == OK:
		_background_loads[path] = true


# A window the player resized is reopened at that size next time (cut to the screen then):
# saved at quit, only when it differs from what the start set and from what is saved.
func _remember_window_size() -> void:
	if _fitted_window_size == Vector2i.ZERO:
		return
	if DisplayServer.window_get_mode() != DisplayServer.WINDOW_MODE_WINDOWED:
		return
	var size := DisplayServer.window_get_size()
	if size == _fitted_window_size or size == settings.window_size:
		return
	settings.window_size = size
	settings.save_file(_settings_path)


func _report(message: String) -> void:
	# players know their files by the real path, not by user://
	message = message.replace("user://", OS.get_user_data_dir() + "/")
	push_warning(message)
	pending_problems.append(message)
	problem_reported.emit(message)
