class_name InputEventCodec
extends RefCounted
## Turns input events into short readable strings for the settings file and back,
## and names them for the controls screen. Only the kinds a player can bind are handled:
## keys (by physical position), gamepad buttons, gamepad axes and mouse buttons.

const JOY_BUTTON_NAMES := {
	JOY_BUTTON_A: "A / Cross",
	JOY_BUTTON_B: "B / Circle",
	JOY_BUTTON_X: "X / Square",
	JOY_BUTTON_Y: "Y / Triangle",
	JOY_BUTTON_BACK: "Back / Select",
	JOY_BUTTON_GUIDE: "Guide",
	JOY_BUTTON_START: "Start",
	JOY_BUTTON_LEFT_STICK: "Left stick press",
	JOY_BUTTON_RIGHT_STICK: "Right stick press",
	JOY_BUTTON_LEFT_SHOULDER: "Left bumper",
	JOY_BUTTON_RIGHT_SHOULDER: "Right bumper",
	JOY_BUTTON_DPAD_UP: "D-pad up",
	JOY_BUTTON_DPAD_DOWN: "D-pad down",
	JOY_BUTTON_DPAD_LEFT: "D-pad left",
	JOY_BUTTON_DPAD_RIGHT: "D-pad right",
}
const JOY_AXIS_NAMES := {
	JOY_AXIS_LEFT_X: ["Left stick left", "Left stick right"],
	JOY_AXIS_LEFT_Y: ["Left stick up", "Left stick down"],
	JOY_AXIS_RIGHT_X: ["Right stick left", "Right stick right"],
	JOY_AXIS_RIGHT_Y: ["Right stick up", "Right stick down"],
	JOY_AXIS_TRIGGER_LEFT: ["Left trigger", "Left trigger"],
	JOY_AXIS_TRIGGER_RIGHT: ["Right trigger", "Right trigger"],
}


## "key:Space", "joy_button:0", "joy_axis:5:+", "mouse:1"; "" for events we do not store.
static func encode(event: InputEvent) -> String:
	if event is InputEventKey:
		var key := event as InputEventKey
		var code := key.physical_keycode if key.physical_keycode != KEY_NONE else key.keycode
		if code == KEY_NONE:
			return ""
		return "key:" + OS.get_keycode_string(code)
	if event is InputEventJoypadButton:
		return "joy_button:%d" % (event as InputEventJoypadButton).button_index
	if event is InputEventJoypadMotion:
		var motion := event as InputEventJoypadMotion
		return "joy_axis:%d:%s" % [motion.axis, "-" if motion.axis_value < 0.0 else "+"]
	if event is InputEventMouseButton:
		return "mouse:%d" % (event as InputEventMouseButton).button_index
	return ""


## The event a string stands for, or null when the string is not one we understand.
static func decode(text: String) -> InputEvent:
	var event := _decode_any(text)
	if event != null:
		event.device = -1  # every device, like the bindings in project.godot
	return event


static func _decode_any(text: String) -> InputEvent:
	var parts := text.strip_edges().split(":")
	if parts.size() < 2:
		return null
	match parts[0]:
		"key":
			var code := OS.find_keycode_from_string(parts[1])
			if code == KEY_NONE:
				return null
			var key := InputEventKey.new()
			key.physical_keycode = code
			return key
		"joy_button":
			if not parts[1].is_valid_int() or int(parts[1]) < 0 or int(parts[1]) >= JOY_BUTTON_MAX:
				return null
			var button := InputEventJoypadButton.new()
			button.button_index = int(parts[1]) as JoyButton
			return button
		"joy_axis":
			if parts.size() != 3 or not parts[1].is_valid_int() or not parts[2] in ["+", "-"]:
				return null
			if int(parts[1]) < 0 or int(parts[1]) >= JOY_AXIS_MAX:
				return null
			var motion := InputEventJoypadMotion.new()
			motion.axis = int(parts[1]) as JoyAxis
			motion.axis_value = -1.0 if parts[2] == "-" else 1.0
			return motion
		"mouse":
			if not parts[1].is_valid_int() or int(parts[1]) <= 0:
				return null
			var mouse := InputEventMouseButton.new()
			mouse.button_index = int(parts[1]) as MouseButton
			return mouse
	return null


## True for events read from a gamepad (buttons and axes).
static func is_gamepad(event: InputEvent) -> bool:
	return event is InputEventJoypadButton or event is InputEventJoypadMotion


## A name a player recognises: "Space", "A / Cross", "Left stick left".
static func describe(event: InputEvent) -> String:
	if event is InputEventKey:
		var key := event as InputEventKey
		var code := key.physical_keycode if key.physical_keycode != KEY_NONE else key.keycode
		return OS.get_keycode_string(code)
	if event is InputEventJoypadButton:
		var index: int = (event as InputEventJoypadButton).button_index
		return JOY_BUTTON_NAMES.get(index, "Button %d" % index)
	if event is InputEventJoypadMotion:
		var motion := event as InputEventJoypadMotion
		var names: Array = JOY_AXIS_NAMES.get(
			motion.axis, ["Axis %d -" % motion.axis, "Axis %d +" % motion.axis]
		)
		return names[0] if motion.axis_value < 0.0 else names[1]
	if event is InputEventMouseButton:
		return "Mouse button %d" % (event as InputEventMouseButton).button_index
	return "?"
