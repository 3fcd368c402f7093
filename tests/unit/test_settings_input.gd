extends GutTest
## Input remapping: bindings are stored as readable codes, survive a save and load, reach
## the InputMap when applied, and "Default controls" brings the shipped bindings back.

const PATH := "user://test_settings_input.cfg"


func after_each() -> void:
	DirAccess.remove_absolute(PATH)
	App.settings.bindings = GameSettings.default_bindings()
	var defaults := GameSettings.new()
	defaults.apply()  # never leave a test binding in the InputMap


func _key(code: Key) -> InputEventKey:
	var key := InputEventKey.new()
	key.physical_keycode = code
	return key


func _joy_button(index: JoyButton) -> InputEventJoypadButton:
	var button := InputEventJoypadButton.new()
	button.button_index = index
	return button


func test_codes_round_trip_for_every_kind_of_event() -> void:
	var motion := InputEventJoypadMotion.new()
	motion.axis = JOY_AXIS_LEFT_Y
	motion.axis_value = -1.0
	var mouse := InputEventMouseButton.new()
	mouse.button_index = MOUSE_BUTTON_LEFT
	for event: InputEvent in [_key(KEY_SPACE), _key(KEY_F3), _joy_button(JOY_BUTTON_START)]:
		assert_eq(
			InputEventCodec.encode(InputEventCodec.decode(InputEventCodec.encode(event))),
			InputEventCodec.encode(event)
		)
	assert_eq(InputEventCodec.encode(motion), "joy_axis:1:-")
	assert_eq(InputEventCodec.encode(InputEventCodec.decode("joy_axis:1:-")), "joy_axis:1:-")
	assert_eq(
		InputEventCodec.encode(InputEventCodec.decode(InputEventCodec.encode(mouse))), "mouse:1"
	)


func test_bad_codes_decode_to_null() -> void:
	for bad: String in ["", "key", "key:NoSuchKey", "joy_button:-1", "joy_button:x", "joy_axis:0"]:
		assert_null(InputEventCodec.decode(bad), bad)
	assert_null(InputEventCodec.decode("joy_axis:0:up"))
	assert_null(InputEventCodec.decode("banana:3"))


func test_decoded_events_match_every_device() -> void:
	assert_eq(InputEventCodec.decode("joy_button:0").device, -1)


func test_keyboard_rebind_keeps_gamepad_bindings() -> void:
	var settings := GameSettings.new()
	settings.rebind("tilt_left", _key(KEY_J), false)
	var codes := PackedStringArray()
	for event in settings.events_for("tilt_left"):
		codes.append(InputEventCodec.encode(event))
	assert_eq(codes, PackedStringArray(["joy_axis:0:-", "key:J"]))


func test_remap_persists_through_the_file_and_reaches_the_input_map() -> void:
	var settings := GameSettings.new()
	settings.rebind("tilt_left", _key(KEY_J), false)
	settings.rebind("pause", _joy_button(JOY_BUTTON_Y), true)
	settings.save_file(PATH)
	var loaded := GameSettings.new()
	assert_eq(loaded.load_file(PATH), "")
	loaded.apply()
	assert_true(InputMap.action_has_event("tilt_left", _key(KEY_J)))
	assert_false(InputMap.action_has_event("tilt_left", _key(KEY_LEFT)), "old key replaced")
	assert_true(InputMap.action_has_event("pause", _joy_button(JOY_BUTTON_Y)))
	assert_true(InputMap.action_has_event("pause", _key(KEY_ESCAPE)), "keyboard side kept")


func test_default_controls_restore_the_shipped_bindings() -> void:
	var settings := GameSettings.new()
	settings.rebind("launch_charge", _key(KEY_Q), false)
	settings.restore_default_bindings()
	settings.apply()
	assert_true(InputMap.action_has_event("launch_charge", _key(KEY_SPACE)))
	assert_false(InputMap.action_has_event("launch_charge", _key(KEY_Q)))


func test_rebinding_an_unknown_action_is_refused() -> void:
	var settings := GameSettings.new()
	settings.rebind("no_such_action", _key(KEY_Q), false)
	assert_push_error("unknown action")
	assert_false(settings.bindings.has("no_such_action"))


func _key_press(code: Key) -> InputEventKey:
	var key := InputEventKey.new()
	key.physical_keycode = code
	key.pressed = true
	return key


func test_the_controls_screen_rebinds_with_the_next_key_and_esc_cancels() -> void:
	var list := BindingList.new()
	add_child_autofree(list)
	var button: Button = list.get_node("tilt_up_key")
	button.pressed.emit()
	assert_true(list.is_capturing())
	list._input(_key_press(KEY_ESCAPE))
	assert_false(list.is_capturing(), "Esc cancels")
	assert_eq(button.text, "Up / W", "nothing changed")
	button.pressed.emit()
	list._input(_key_press(KEY_I))
	assert_eq(button.text, "I")
	assert_eq(InputEventCodec.encode(App.settings.events_for("tilt_up")[-1]), "key:I")
	var pad: Button = list.get_node("tilt_up_pad")
	pad.pressed.emit()
	var trigger := InputEventJoypadMotion.new()
	trigger.axis = JOY_AXIS_TRIGGER_LEFT
	trigger.axis_value = 0.9
	list._input(trigger)
	assert_eq(pad.text, "Left trigger")


func test_the_controls_screen_removes_a_binding_but_pause_keeps_one() -> void:
	var list := BindingList.new()
	add_child_autofree(list)
	var restart: Button = list.get_node("game_restart_key")
	restart.gui_input.emit(_key_press(KEY_DELETE))
	assert_eq(restart.text, "(none)")
	assert_true(
		App.settings.events_for("game_restart").all(InputEventCodec.is_gamepad), "keys gone"
	)
	var right_click := InputEventMouseButton.new()
	right_click.button_index = MOUSE_BUTTON_RIGHT
	right_click.pressed = true
	var restart_pad: Button = list.get_node("game_restart_pad")
	restart_pad.gui_input.emit(right_click)
	assert_eq(restart_pad.text, "(none)", "a right click removes too")
	for column in ["pause_key", "pause_pad"]:
		var pause: Button = list.get_node(column)
		var before := pause.text
		pause.gui_input.emit(_key_press(KEY_BACKSPACE) if column == "pause_key" else right_click)
		assert_string_contains(pause.text, before, "%s: the pause binding stays" % column)
		assert_string_contains(pause.text, "Pause needs one", column)
