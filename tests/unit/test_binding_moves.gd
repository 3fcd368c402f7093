extends GutTest
## A key or button already bound to another action of the same game: the controls screen
## asks whether to move it and names that action; moving swaps the old binding over so no
## action is left without one; a move that would leave one empty is refused.


func after_each() -> void:
	App.settings.bindings = GameSettings.default_bindings()
	GameSettings.new().apply()  # never leave a test binding in the InputMap


func _key(code: Key) -> InputEventKey:
	var key := InputEventKey.new()
	key.physical_keycode = code
	return key


func _key_press(code: Key) -> InputEventKey:
	var key := _key(code)
	key.pressed = true
	return key


func _codes(settings: GameSettings, action: String) -> PackedStringArray:
	var codes := PackedStringArray()
	for event in settings.events_for(action):
		codes.append(InputEventCodec.encode(event))
	return codes


func test_h_for_calibrate_clashes_with_hard_mode_but_space_across_games_does_not() -> void:
	var settings := GameSettings.new()
	assert_eq(
		BindingMoves.clashes(settings, "maze_calibrate", _key(KEY_H)),
		PackedStringArray(["maze_hard_mode"])
	)
	# Space resets the maze and launches in pachinko: never in one game together
	assert_eq(BindingMoves.clashes(settings, "maze_reset", _key(KEY_SPACE)).size(), 0)
	# Escape is Pause's, a general action: it clashes with a maze one
	assert_eq(
		BindingMoves.clashes(settings, "maze_easy_mode", _key(KEY_ESCAPE)),
		PackedStringArray(["pause"])
	)
	# the shipped controls share A (launch, start a game): that pair is no clash
	var a := InputEventJoypadButton.new()
	a.button_index = JOY_BUTTON_A
	assert_eq(BindingMoves.clashes(settings, "game_start", a).size(), 0)


func test_moving_h_swaps_calibrates_old_key_over_to_hard_mode() -> void:
	var settings := GameSettings.new()
	var result := BindingMoves.move(settings, "maze_calibrate", _key(KEY_H), false)
	assert_true(result["ok"])
	assert_eq(_codes(settings, "maze_calibrate"), PackedStringArray(["joy_button:2", "key:H"]))
	assert_eq(
		_codes(settings, "maze_hard_mode"),
		PackedStringArray(["joy_button:9", "key:C"]),
		"C swaps over"
	)


func test_a_move_that_would_leave_an_action_without_a_binding_is_refused() -> void:
	var settings := GameSettings.new()
	settings.clear_binding("maze_calibrate", false)  # calibrate has no key to give back
	var result := BindingMoves.move(settings, "maze_calibrate", _key(KEY_H), false)
	assert_false(result["ok"])
	assert_eq(result["stuck"], "maze_hard_mode")
	assert_eq(
		_codes(settings, "maze_hard_mode"),
		PackedStringArray(["key:H", "joy_button:9"]),
		"unchanged"
	)
	# an action with a second key keeps it and needs no swap
	var result_w := BindingMoves.move(settings, "maze_calibrate", _key(KEY_W), false)
	assert_true(result_w["ok"])
	assert_eq(_codes(settings, "tilt_up"), PackedStringArray(["key:Up", "joy_axis:1:-"]))


func test_the_controls_screen_asks_names_the_other_action_and_moves_on_yes() -> void:
	var list: BindingList = BindingList.new()
	add_child_autofree(list)
	var calibrate: Button = list.get_node("maze_calibrate_key")
	calibrate.pressed.emit()
	list.get_viewport().push_input(_key_press(KEY_H))
	var dialog := list.move_dialog()
	assert_not_null(dialog, "it asks")
	assert_true(dialog.visible)
	assert_string_contains(dialog.dialog_text, "H is already used by “Maze: hard mode (holes)”")
	assert_string_contains(dialog.dialog_text, "Move it to “Maze: calibrate the tilt”?")
	assert_string_contains(dialog.dialog_text, "“Maze: hard mode (holes)” gets C instead.")
	assert_eq(calibrate.text, "C", "nothing moves before the answer")
	dialog.get_cancel_button().pressed.emit()
	assert_eq(_codes(App.settings, "maze_hard_mode")[0], "key:H", "Keep it there keeps it")
	calibrate.pressed.emit()
	list.get_viewport().push_input(_key_press(KEY_H))
	dialog.confirmed.emit()
	assert_eq(calibrate.text, "H")
	assert_eq((list.get_node("maze_hard_mode_key") as Button).text, "C")


func test_the_controls_screen_says_why_a_move_is_refused() -> void:
	App.settings.clear_binding("maze_calibrate", false)
	var list: BindingList = BindingList.new()
	add_child_autofree(list)
	(list.get_node("maze_calibrate_key") as Button).pressed.emit()
	list.get_viewport().push_input(_key_press(KEY_H))
	var note := list.refusal()
	assert_not_null(note)
	assert_string_contains(note.dialog_text, "H is the only key of “Maze: hard mode (holes)”")
	assert_eq(_codes(App.settings, "maze_hard_mode")[0], "key:H")


func test_the_space_row_says_what_it_does() -> void:
	assert_eq(BindingList.action_title("maze_reset"), "Maze: start the board again")
