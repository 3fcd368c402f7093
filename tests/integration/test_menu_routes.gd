extends GutTest
## The menus driven the way a player without a mouse does: input events only (keys, or a
## gamepad's buttons), through real scene changes, from the title screen to a level select,
## to one of the player's own boards in play, and back.

const MAIN_MENU := "res://scenes/menu/main_menu.tscn"
const LEVEL_SELECT := "res://scenes/menu/level_select.tscn"
const PACHINKO := "res://scenes/pachinko/pachinko_game.tscn"
## The player's own boards folder: only boards there (or shipped) play. The test's board
## sorts first and is removed afterwards.
const ROOT := "user://boards"
const MY_BOARD := "0_test_menu_route.board"
## Where the trap test's file dialogs open.
const EXPORTS := "user://test_menu_routes_exports"
## Enough frames for a deferred scene change and a level select's loading.
const MAX_FRAMES := 600

var _keys := true


func before_each() -> void:
	App.level_select_kind = "pachinko"
	# the mouse rests in a corner: no tooltip (which would take the first Esc) pops up
	var away := InputEventMouseMotion.new()
	away.position = Vector2(2, 2)
	get_tree().root.push_input(away)
	DirAccess.make_dir_recursive_absolute(ROOT + "/pachinko")
	DirAccess.make_dir_recursive_absolute(EXPORTS)
	var file := FileAccess.open("%s/pachinko/%s" % [ROOT, MY_BOARD], FileAccess.WRITE)
	file.store_buffer(FileAccess.get_file_as_bytes("res://levels/pachinko/classic.board"))
	file.close()


func after_each() -> void:
	get_tree().paused = false
	var scene := get_tree().current_scene
	if scene != null:
		get_tree().current_scene = null
		scene.queue_free()
	await get_tree().process_frame


func after_all() -> void:
	DirAccess.remove_absolute("%s/pachinko/%s" % [ROOT, MY_BOARD])
	for file_name in DirAccess.get_files_at(EXPORTS):
		DirAccess.remove_absolute(EXPORTS.path_join(file_name))
	DirAccess.remove_absolute(EXPORTS)
	# the route picked the board this test removes: later scenes must not ask for it
	App.request_board("pachinko", "res://levels/pachinko/classic.board")


func test_escape_leaves_the_level_select_without_a_script_error() -> void:
	var screen := await _open(App.go_to_level_select.bind("pachinko"), LEVEL_SELECT)
	await _loaded(screen)
	# pushed into the screen's viewport as a window delivers it (input, GUI, unhandled input)
	var cancel := InputEventAction.new()
	cancel.action = &"ui_cancel"
	cancel.pressed = true
	screen.get_viewport().push_input(cancel)
	var menu := await _became(MAIN_MENU)
	assert_not_null(menu, "Esc goes back to the title screen")
	assert_engine_error_count(0, "no error on the way out (was: set_input_as_handled on null)")


func test_down_enter_enter_on_a_card_never_writes_a_file() -> void:
	# the old trap: Down went to the card's Export button, Enter opened the file dialog and a
	# second Enter wrote <documents>/classic.board without the player meaning to export
	_keys = true
	var screen := await _open(App.go_to_level_select.bind("pachinko"), LEVEL_SELECT)
	await _loaded(screen)
	var dialogs := screen.get_node("%Dialogs")
	dialogs.set("start_folder", ProjectSettings.globalize_path(EXPORTS))
	var exported: Array[String] = []
	dialogs.connect(
		"export_chosen", func(_board: String, target: String) -> void: exported.append(target)
	)
	var targets: Array[String] = []
	for dialog in dialogs.get_children():
		if dialog is FileDialog:
			targets.append((dialog as FileDialog).current_path)
	assert_eq(_focused_text(), "", "a card has the focus")
	for action: String in ["ui_down", "ui_accept", "ui_accept"]:
		await _press(action)
	assert_eq(exported, [] as Array[String], "nothing was exported")
	assert_eq(DirAccess.get_files_at(EXPORTS).size(), 0, "no file in the start folder")
	for target in targets:
		assert_false(FileAccess.file_exists(target), "no file at %s" % target)
	for stray in exported:
		DirAccess.remove_absolute(stray)  # what the old trap wrote, cleaned away


func test_keys_alone_reach_a_board_of_my_own_and_come_back() -> void:
	_keys = true
	await _route_to_my_board_and_back()


func test_a_gamepad_alone_reaches_a_board_of_my_own_and_comes_back() -> void:
	_keys = false
	await _route_to_my_board_and_back()


# A blind trial took 49 s from launch to its first shot, 27 of them to reach a board through
# the list: from the title two presses now fire the first ball (Enter plays Classic; Space
# on its rules card starts the game and draws the flipper back, let go it fires).
func test_two_presses_from_the_title_fire_the_first_ball() -> void:
	_keys = true
	App.request_board("pachinko", "")  # nothing played yet this run
	var menu := await _open(App.go_to_menu, MAIN_MENU)
	assert_not_null(menu)
	assert_eq(_focused_text(), "Play Pachinko", "Play is the default")
	await _press("ui_accept")
	var game := await _became(PACHINKO) as PachinkoGame
	assert_not_null(game, "Enter on the title opens a board")
	assert_eq(game.rules.level.board_id, "pachinko_classic", "Classic, for a new player")
	assert_true(game.instructions.visible, "its rules card is up")
	await wait_seconds(0.6)  # the card takes no key in its first half second
	var space := _event_for("launch_charge")
	space.set("pressed", true)
	Input.parse_input_event(space)
	await wait_process_frames(20)
	assert_eq(game.rules.state, PachinkoRules.State.PLAYING, "Space starts the game")
	space.set("pressed", false)
	Input.parse_input_event(space)
	await wait_process_frames(2)
	assert_eq(game.rules.ledger.shots, 1, "and let go fires the first ball")


func _route_to_my_board_and_back() -> void:
	var menu := await _open(App.go_to_menu, MAIN_MENU)
	assert_not_null(menu)
	assert_eq(_focused_text(), "Play Pachinko", "the title screen focuses Play")
	await _press("ui_down")
	assert_eq(_focused_text(), "Pachinko boards")
	await _press("ui_accept")
	var screen := await _became(LEVEL_SELECT)
	assert_not_null(screen, "Enter / A opens the pachinko level select")
	await _loaded(screen)
	var wanted := "%s/pachinko/%s" % [ROOT, MY_BOARD]
	var seen: Array[String] = []
	for step in 12:
		var card := get_viewport().gui_get_focus_owner()
		assert_true(card is Button and card.get("board_path") != null, "focus is on a card")
		if card == null or str(card.get("board_path")) == wanted:
			break
		seen.append(str(card.get("board_path")).get_file())
		await _press("ui_down")
	var focused := get_viewport().gui_get_focus_owner()
	assert_eq(
		str(focused.get("board_path")) if focused != null else "", wanted, "Down reaches My boards"
	)
	assert_lt(seen.size(), 4, "one press per row: %s" % ", ".join(seen))
	await _press("board_actions")
	var card_menu := (screen as LevelSelect).card_menu()
	assert_true(card_menu.visible, "X / Square opens the card's menu")
	await _press("ui_cancel")
	assert_false(card_menu.visible, "Esc / B closes it again")
	assert_eq(str(get_viewport().gui_get_focus_owner().get("board_path")), wanted, "on my card")
	await _press("ui_accept")
	var game := await _became(PACHINKO)
	assert_not_null(game, "Enter / A plays the board")
	assert_eq(App.current_board_path("pachinko"), wanted, "it is my board that plays")
	await _press("pause")
	assert_true(get_tree().paused, "the pause menu opened")
	assert_eq(_focused_text(), "Resume")
	for step in 3:
		await _press("ui_down")
	assert_eq(_focused_text(), "Other boards")
	await _press("ui_accept")
	var boards := await _became(LEVEL_SELECT)
	assert_not_null(boards, "back on the game's list of boards, not the title screen")
	assert_false(get_tree().paused)
	assert_eq(App.level_select_kind, "pachinko", "the pachinko boards")
	assert_engine_error_count(0)


func _focused_text() -> String:
	var focused := get_viewport().gui_get_focus_owner()
	return (focused as Button).text if focused is Button else ""


# Presses and lets go of `action` as the player's device would: its first key, or its first
# gamepad button when this test plays with a pad.
func _press(action: String) -> void:
	for pressed: bool in [true, false]:
		var event := _event_for(action)
		if event == null:
			fail_test("%s has no %s binding" % [action, "key" if _keys else "gamepad"])
			return
		event.set("pressed", pressed)
		Input.parse_input_event(event)
		await get_tree().process_frame
	await get_tree().process_frame


func _event_for(action: String) -> InputEvent:
	for event in InputMap.action_get_events(action):
		if _keys and event is InputEventKey:
			var key := InputEventKey.new()
			key.physical_keycode = (event as InputEventKey).physical_keycode
			key.keycode = (event as InputEventKey).keycode
			if key.keycode == KEY_NONE:
				key.keycode = key.physical_keycode
			if key.physical_keycode == KEY_NONE:
				key.physical_keycode = key.keycode
			key.key_label = key.keycode  # a real keyboard's events carry all three
			return key
		if not _keys and event is InputEventJoypadButton:
			var button := InputEventJoypadButton.new()
			button.button_index = (event as InputEventJoypadButton).button_index
			return button
	return null


func _open(change: Callable, scene_path: String) -> Node:
	change.call()
	return await _became(scene_path)


func _became(scene_path: String) -> Node:
	for frame in MAX_FRAMES:
		var scene := get_tree().current_scene
		if scene != null and scene.scene_file_path == scene_path and scene.is_node_ready():
			await get_tree().process_frame
			return scene
		await get_tree().process_frame
	return null


func _loaded(screen: Node) -> void:
	for frame in MAX_FRAMES:
		if not (screen as LevelSelect).is_loading():
			break
		await get_tree().process_frame
	await get_tree().process_frame
