class_name BindingList
extends GridContainer
## The controls part of the settings screen: one row per game action with its keyboard and
## gamepad bindings. Choosing a binding waits for the next key (or gamepad button / stick),
## which replaces that column's binding; Esc cancels a key capture, any key a gamepad one.
## Delete, Backspace or a right click on a binding removes it (pause always keeps one:
## removing its last binding brings the default back). A key or button another action of
## the same game already uses asks first whether to move it (binding_moves.gd), naming that
## action; a move that would leave it with nothing is refused.

## A binding changed (the settings were updated; the owner saves them).
signal binding_changed
## A capture started (true) or ended (false); the owner ignores its own shortcuts meanwhile.
signal capture_toggled(capturing: bool)

const AXIS_THRESHOLD := 0.6
const TITLE_MIN_WIDTH := 220.0
## A binding button's least width as designed (a landscape window).
const BUTTON_WIDTH := 300.0
const ACTION_NAMES := {
	"launch_charge": "Pachinko: launch (hold to charge)",
	"launch_handle": "Pachinko: hold the handle (stream)",
	"handle_stronger": "Pachinko: turn the handle stronger",
	"handle_weaker": "Pachinko: turn the handle weaker",
	"tilt_left": "Maze: tilt left",
	"tilt_right": "Maze: tilt right",
	"tilt_up": "Maze: tilt up",
	"tilt_down": "Maze: tilt down",
	"tilt_fine": "Maze: fine tilt (hold for half tilt)",
	"maze_reset": "Maze: start the board again",
	"maze_hard_mode": "Maze: hard mode (holes)",
	"maze_easy_mode": "Maze: easy mode",
	"maze_calibrate": "Maze: calibrate the tilt",
	"game_start": "Start a game",
	"game_restart": "Restart",
	"pause": "Pause",
	"toggle_frame_counter": "Show / hide frame counter",
	"board_actions": "Level select: a board's menu (play, export, delete)",
}

## How wide each binding button is at least (a portrait window asks for narrower ones).
var button_width := BUTTON_WIDTH:
	set = set_button_width

var _capture_action := ""
var _capture_gamepad := false
var _capture_button: Button = null
var _move_dialog: ConfirmationDialog = null
var _refusal: AcceptDialog = null
var _pending_move := {}


func _ready() -> void:
	columns = 3
	rebuild()


func _input(event: InputEvent) -> void:
	if _capture_button == null:
		return
	if event is InputEventKey and event.is_pressed() and not event.is_echo():
		var key := event as InputEventKey
		if _capture_gamepad or key.physical_keycode == KEY_ESCAPE:
			_end_capture()
		else:
			_finish_capture(_key_event(key))
		get_viewport().set_input_as_handled()
	elif _capture_gamepad and event is InputEventJoypadButton and event.is_pressed():
		var button := InputEventJoypadButton.new()
		button.button_index = (event as InputEventJoypadButton).button_index
		_finish_capture(button)
		get_viewport().set_input_as_handled()
	elif _capture_gamepad and event is InputEventJoypadMotion:
		var motion := event as InputEventJoypadMotion
		if absf(motion.axis_value) >= AXIS_THRESHOLD:
			var axis := InputEventJoypadMotion.new()
			axis.axis = motion.axis
			axis.axis_value = signf(motion.axis_value)
			_finish_capture(axis)
		get_viewport().set_input_as_handled()
	elif event is InputEventJoypadButton or event is InputEventJoypadMotion:
		get_viewport().set_input_as_handled()  # no menu navigation while a key is awaited


## True while waiting for the player to press the new binding.
func is_capturing() -> bool:
	return _capture_button != null


## Readable name of an action for the list.
## Sets how wide each binding button is at least, for the rows there are and those to come.
func set_button_width(width: float) -> void:
	button_width = width
	for child in get_children():
		if child is Button:
			(child as Button).custom_minimum_size.x = width


static func action_title(action: String) -> String:
	return ACTION_NAMES.get(action, action.capitalize())


## Recreates every row from the current settings.
func rebuild() -> void:
	for child in get_children():
		remove_child(child)
		child.queue_free()
	_add_header("Action")
	_add_header("Keyboard")
	_add_header("Gamepad")
	for action in GameSettings.remappable_actions():
		var title := Label.new()
		title.text = action_title(action)
		title.size_flags_horizontal = Control.SIZE_EXPAND_FILL
		# a long action name wraps rather than pushing the buttons out of a narrow window
		title.autowrap_mode = TextServer.AUTOWRAP_WORD
		title.custom_minimum_size.x = TITLE_MIN_WIDTH
		add_child(title)
		add_child(_binding_button(action, false))
		add_child(_binding_button(action, true))


## The first binding button, for focus hand-off from the controls above.
func first_button() -> Button:
	for child in get_children():
		if child is Button:
			return child as Button
	return null


func _add_header(text: String) -> void:
	var header := Label.new()
	header.text = text
	header.theme_type_variation = &"HintLabel"
	add_child(header)


func _binding_button(action: String, gamepad: bool) -> Button:
	var button := Button.new()
	button.name = "%s_%s" % [action, "pad" if gamepad else "key"]
	button.custom_minimum_size = Vector2(button_width, 0)
	button.theme_type_variation = &"SmallButton"
	button.clip_text = true
	button.text = _describe(action, gamepad)
	button.tooltip_text = (
		"Choose, then press the new %s. Delete or right-click removes it."
		% ["button" if gamepad else "key"]
	)
	button.pressed.connect(_start_capture.bind(action, gamepad, button))
	button.gui_input.connect(_on_binding_input.bind(action, gamepad, button))
	return button


## Removes the binding of one column on Delete, Backspace or a right click.
func _on_binding_input(event: InputEvent, action: String, gamepad: bool, button: Button) -> void:
	if is_capturing() or not event.is_pressed() or event.is_echo():
		return
	var key := event as InputEventKey
	var mouse := event as InputEventMouseButton
	var wants_clear := key != null and key.physical_keycode in [KEY_DELETE, KEY_BACKSPACE]
	wants_clear = wants_clear or (mouse != null and mouse.button_index == MOUSE_BUTTON_RIGHT)
	if not wants_clear:
		return
	var cleared := App.settings.clear_binding(action, gamepad)
	button.text = _describe(action, gamepad)
	if not cleared:
		button.text += " (%s needs one)" % action_title(action)
	button.accept_event()
	binding_changed.emit()


func _describe(action: String, gamepad: bool) -> String:
	var names := PackedStringArray()
	for event in App.settings.events_for(action):
		if InputEventCodec.is_gamepad(event) == gamepad and not event is InputEventMouseButton:
			names.append(InputEventCodec.describe(event))
	return " / ".join(names) if not names.is_empty() else "(none)"


func _start_capture(action: String, gamepad: bool, button: Button) -> void:
	_end_capture()
	_capture_action = action
	_capture_gamepad = gamepad
	_capture_button = button
	button.text = "Press a button… (any key cancels)" if gamepad else "Press a key… (Esc cancels)"
	capture_toggled.emit(true)


func _finish_capture(event: InputEvent) -> void:
	event.device = -1
	var action := _capture_action
	var gamepad := _capture_gamepad
	_end_capture()
	var others := BindingMoves.clashes(App.settings, action, event)
	if others.is_empty():
		App.settings.rebind(action, event, gamepad)
		_refresh(action, gamepad)
		return
	_ask_to_move(action, event, gamepad, others)


## The dialog asking whether to move a binding another action uses (null until first asked).
func move_dialog() -> ConfirmationDialog:
	return _move_dialog


## The note saying a binding cannot be moved (null until first needed).
func refusal() -> AcceptDialog:
	return _refusal


# Asks whether to take `event` off `others` and bind it to `action`, or says why it can't.
func _ask_to_move(
	action: String, event: InputEvent, gamepad: bool, others: PackedStringArray
) -> void:
	var shown := InputEventCodec.describe(event)
	var names := PackedStringArray()
	for other in others:
		names.append("“%s”" % action_title(other))
	var plan := BindingMoves.plan(App.settings, action, event, gamepad)
	if not plan["ok"]:
		if _refusal == null:
			_refusal = AcceptDialog.new()
			_refusal.title = "Binding not moved"
			add_child(_refusal)
		var stuck: String = plan["stuck"]
		_refusal.dialog_text = (
			"%s is the only %s of “%s”, so it stays there.\nGive “%s” another one first."
			% [shown, "button" if gamepad else "key", action_title(stuck), action_title(stuck)]
		)
		_refusal.popup_centered()
		return
	if _move_dialog == null:
		_move_dialog = ConfirmationDialog.new()
		_move_dialog.title = "Already in use"
		_move_dialog.ok_button_text = "Move it"
		_move_dialog.cancel_button_text = "Keep it there"
		_move_dialog.confirmed.connect(_on_move_confirmed)
		add_child(_move_dialog)
	var lines := PackedStringArray(
		[
			"%s is already used by %s." % [shown, " and ".join(names)],
			"Move it to “%s”?" % action_title(action),
		]
	)
	var swaps: Dictionary = plan["swaps"]
	for other: String in swaps:
		var swapped: InputEvent = swaps[other]
		lines.append(
			"“%s” gets %s instead." % [action_title(other), InputEventCodec.describe(swapped)]
		)
	_move_dialog.dialog_text = "\n".join(lines)
	_pending_move = {"action": action, "event": event, "gamepad": gamepad}
	_move_dialog.popup_centered()
	_move_dialog.get_ok_button().grab_focus.call_deferred()


func _on_move_confirmed() -> void:
	if _pending_move.is_empty():
		return
	var action: String = _pending_move["action"]
	var gamepad: bool = _pending_move["gamepad"]
	var event: InputEvent = _pending_move["event"]
	BindingMoves.move(App.settings, action, event, gamepad)
	_pending_move = {}
	_refresh(action, gamepad)


# Shows every binding again after a change and keeps the focus on the changed one.
func _refresh(action: String, gamepad: bool) -> void:
	for child in get_children():
		var button := child as Button
		if button != null:
			var parts := String(button.name).rsplit("_", true, 1)
			if parts.size() == 2:
				button.text = _describe(parts[0], parts[1] == "pad")
	var changed := get_node_or_null("%s_%s" % [action, "pad" if gamepad else "key"]) as Button
	if changed != null:
		changed.grab_focus.call_deferred()
	binding_changed.emit()


func _end_capture() -> void:
	if _capture_button == null:
		return
	_capture_button.text = _describe(_capture_action, _capture_gamepad)
	_capture_button = null
	capture_toggled.emit.call_deferred(false)


func _key_event(pressed: InputEventKey) -> InputEventKey:
	var key := InputEventKey.new()
	key.physical_keycode = pressed.physical_keycode
	if key.physical_keycode == KEY_NONE:
		key.physical_keycode = pressed.keycode
	return key
