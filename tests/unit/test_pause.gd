extends GutTest
## The pause menu: the pause action stops everything that is not the menu itself, resume
## lets it run again, restart unpauses and asks the game to restart.

const PauseScene := preload("res://scenes/common/pause_menu.tscn")

var _menu: PauseMenu
var _world: Node


func before_each() -> void:
	_world = Node.new()  # stands in for a game's simulation node (inherits the pause)
	add_child_autofree(_world)
	_menu = PauseScene.instantiate() as PauseMenu
	add_child_autofree(_menu)


func after_each() -> void:
	get_tree().paused = false


func _press(action: String) -> void:
	var event := InputEventAction.new()
	event.action = action
	event.pressed = true
	_menu._unhandled_input(event)


func test_pause_action_stops_the_world_and_not_the_menu() -> void:
	assert_true(_world.can_process())
	_press("pause")
	assert_true(get_tree().paused)
	assert_true(_menu.is_open())
	assert_false(_world.can_process(), "the simulation does not run while paused")
	assert_true(_menu.can_process(), "the menu still answers")


func test_pause_again_resumes() -> void:
	_press("pause")
	_press("pause")
	assert_false(get_tree().paused)
	assert_false(_menu.is_open())
	assert_true(_world.can_process())


func test_cancel_resumes() -> void:
	_press("pause")
	_press("ui_cancel")
	assert_false(get_tree().paused)


func test_resume_button_gets_focus_for_keyboard_and_gamepad() -> void:
	_press("pause")
	var resume: Button = _menu.get_node("%ResumeButton")
	assert_true(resume.has_focus())


func test_restart_unpauses_and_asks_the_game() -> void:
	watch_signals(_menu)
	_press("pause")
	(_menu.get_node("%RestartButton") as Button).pressed.emit()
	assert_signal_emitted(_menu, "restart_requested")
	assert_false(get_tree().paused)


func test_settings_open_over_the_pause_menu_and_close_with_cancel() -> void:
	_press("pause")
	(_menu.get_node("%SettingsButton") as Button).pressed.emit()
	var settings := _menu.get_node_or_null("SettingsMenu")
	assert_not_null(settings)
	assert_true(settings.can_process(), "settings work while paused")
	_press("pause")
	assert_true(get_tree().paused, "the pause action does not leak past the settings screen")


func _pause_menu_in(node: Node) -> PauseMenu:
	for child in node.get_children():
		if child is PauseMenu:
			return child as PauseMenu
	return null


# Only the maze scene: headless, the pachinko scene's key names call a DisplayServer
# function that prints engine errors, which GUT counts as failures.
func test_the_maze_game_stops_under_its_pause_menu() -> void:
	for path: String in ["res://scenes/maze/maze_game.tscn"]:
		var packed: PackedScene = load(path)
		var game := packed.instantiate()
		add_child_autofree(game)
		var menu := _pause_menu_in(game)
		assert_not_null(menu, "%s instances the pause menu" % path)
		if menu == null:
			continue
		menu.open()
		assert_false(game.can_process(), "%s: the game stops while paused" % path)
		assert_true(menu.can_process())
		menu.close()
		assert_true(game.can_process(), "%s: and runs again after resume" % path)


# QA: settings opened from the pause menu scrolled past their first row (Master volume),
# which had the focus, so the player saw neither the row nor where the keys were.
func test_settings_from_the_pause_menu_show_their_focused_first_row() -> void:
	_press("pause")
	_menu.get_node("%SettingsButton").emit_signal("pressed")
	await wait_process_frames(6)
	var settings: Control = _menu.open_settings_screen()
	var scroll: ScrollContainer = settings.get_node("Margin/Panel/Box/Scroll")
	var master: Control = settings.get_node("%MasterSlider")
	assert_eq(settings.get_viewport().gui_get_focus_owner(), master, "Master volume has focus")
	assert_eq(scroll.scroll_vertical, 0, "and the list is at its top, where that row is")


# Trial 5: the pause menu had no way back to the title. "Main menu" comes after "Other
# boards", and the arrow keys walk the buttons top to bottom in the order shown.
func test_a_main_menu_button_follows_other_boards_in_the_focus_order() -> void:
	_press("pause")
	var main: Button = _menu.get_node_or_null("%MainMenuButton")
	assert_not_null(main, "a Main menu button")
	if main == null:
		return
	assert_eq(main.text, "Main menu")
	assert_true(main.pressed.is_connected(_menu._on_main_menu_pressed), "it goes to the title")
	var order: Array[Button] = [
		_menu.get_node("%ResumeButton"),
		_menu.get_node("%RestartButton"),
		_menu.get_node("%SettingsButton"),
		_menu.get_node("%MenuButton"),
		main,
	]
	await wait_process_frames(2)  # laid out: the focus walk reads the buttons' places
	for i in order.size() - 1:
		var below := order[i].find_valid_focus_neighbor(SIDE_BOTTOM)
		assert_eq(below, order[i + 1], "Down from %s" % order[i].text)
