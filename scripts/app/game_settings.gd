class_name GameSettings
extends RefCounted
## The player's settings: volumes, window mode, frame counter, tilt sensitivity and the
## key and gamepad bindings of every game action. Saved as a readable INI file
## (user://settings.cfg). A damaged or unknown-version file is reported by `load_file`
## and replaced with defaults; it never stops the game.

## Emitted after any value changed through a setter or a load.
signal changed

const VERSION := 1
const MIN_TILT_SENSITIVITY := 0.25
const MAX_TILT_SENSITIVITY := 3.0
const IniText := preload("res://scripts/app/ini_text.gd")
const Codec := preload("res://scripts/app/input_event_codec.gd")
const FILE_HEADER := (
	"Board Studio settings (format version %d). Delete this file to restore the defaults.\n"
	+ "Bindings: key:<name>, joy_button:<index>, joy_axis:<index>:<+|->, mouse:<index>."
)

## Master volume, 0 (silent) to 1 (full).
var master_volume := 1.0
## Sound effects volume, 0 to 1.
var sfx_volume := 1.0
## Fullscreen when true, a window when false.
var fullscreen := false
## Show the frames-per-second counter in a corner.
var show_frame_counter := false
## Multiplier on the maze tilt from keys and sticks.
var tilt_sensitivity := 1.0
## Every maze board open from the start, instead of one after another.
var unlock_all_boards := false
## Action name -> Array of InputEvent, for every action in `remappable_actions()`.
var bindings := {}


func _init() -> void:
	bindings = default_bindings()


## Every action the project defines. Godot's own ui_* actions drive the menus and stay fixed,
## so the player can never rebind themselves out of the settings screen.
static func remappable_actions() -> PackedStringArray:
	var actions := PackedStringArray()
	for property in ProjectSettings.get_property_list():
		var name: String = property["name"]
		if name.begins_with("input/") and not name.begins_with("input/ui_"):
			actions.append(name.trim_prefix("input/"))
	return actions


## The bindings project.godot ships with, read fresh so earlier remaps never leak in.
static func default_bindings() -> Dictionary:
	var result := {}
	for action in remappable_actions():
		var entry: Dictionary = ProjectSettings.get_setting("input/" + action, {})
		var events: Array[InputEvent] = []
		for event: InputEvent in entry.get("events", []):
			events.append(event.duplicate() as InputEvent)
		result[action] = events
	return result


## Puts every value back to its default.
func reset_to_defaults() -> void:
	master_volume = 1.0
	sfx_volume = 1.0
	fullscreen = false
	show_frame_counter = false
	tilt_sensitivity = 1.0
	unlock_all_boards = false
	bindings = default_bindings()
	changed.emit()


## The events bound to an action (a copy).
func events_for(action: String) -> Array[InputEvent]:
	var events: Array[InputEvent] = []
	var bound: Array = bindings.get(action, [])
	events.assign(bound)
	return events


## Replaces the keyboard (gamepad = false) or gamepad events of an action with one event,
## keeping the other kind as it was.
func rebind(action: String, event: InputEvent, gamepad: bool) -> void:
	if not bindings.has(action):
		push_error("GameSettings.rebind: unknown action '%s'" % action)
		return
	var events: Array[InputEvent] = []
	for old: InputEvent in bindings[action]:
		if Codec.is_gamepad(old) != gamepad:
			events.append(old)
	events.append(event)
	bindings[action] = events
	changed.emit()


## Restores the shipped bindings of every action.
func restore_default_bindings() -> void:
	bindings = default_bindings()
	changed.emit()


## Sets one value by name (the settings screen's sliders and toggles), clamped to its range.
func set_value(key: String, value: Variant) -> void:
	match key:
		"master_volume":
			var volume: float = value
			master_volume = clampf(volume, 0.0, 1.0)
		"sfx_volume":
			var volume: float = value
			sfx_volume = clampf(volume, 0.0, 1.0)
		"fullscreen":
			var on: bool = value
			fullscreen = on
		"show_frame_counter":
			var on: bool = value
			show_frame_counter = on
		"unlock_all_boards":
			var on: bool = value
			unlock_all_boards = on
		"tilt_sensitivity":
			var sensitivity: float = value
			tilt_sensitivity = clampf(sensitivity, MIN_TILT_SENSITIVITY, MAX_TILT_SENSITIVITY)
		_:
			push_error("GameSettings.set_value: unknown setting '%s'" % key)
			return
	changed.emit()


## Pushes the values into the engine: bus volumes, window mode, the InputMap.
func apply() -> void:
	_apply_bus("Master", master_volume)
	_apply_bus("SFX", sfx_volume)
	if DisplayServer.get_name() != "headless":
		var mode := DisplayServer.window_get_mode()
		var is_full := mode == DisplayServer.WINDOW_MODE_FULLSCREEN
		is_full = is_full or mode == DisplayServer.WINDOW_MODE_EXCLUSIVE_FULLSCREEN
		if fullscreen and not is_full:
			DisplayServer.window_set_mode(DisplayServer.WINDOW_MODE_FULLSCREEN)
		elif not fullscreen and is_full:
			DisplayServer.window_set_mode(DisplayServer.WINDOW_MODE_WINDOWED)
	for action: String in bindings:
		if not InputMap.has_action(action):
			continue
		InputMap.action_erase_events(action)
		for event: InputEvent in bindings[action]:
			InputMap.action_add_event(action, event)


## Writes the settings as readable text. Returns OK or the file error.
func save_file(path: String) -> Error:
	var input := {}
	for action: String in bindings:
		var codes: Array[String] = []
		for event: InputEvent in bindings[action]:
			var code := Codec.encode(event)
			if not code.is_empty():
				codes.append(code)
		input[action] = codes
	var sections := [
		["meta", {"version": VERSION}],
		["audio", {"master_volume": master_volume, "sfx_volume": sfx_volume}],
		["display", {"fullscreen": fullscreen, "show_frame_counter": show_frame_counter}],
		["controls", {"tilt_sensitivity": tilt_sensitivity}],
		["progress", {"unlock_all_boards": unlock_all_boards}],
		["input", input],
	]
	var error := IniText.write_file(path, IniText.format(FILE_HEADER % VERSION, sections))
	if error != OK:
		push_error("Could not save settings to %s: %s" % [path, error_string(error)])
	return error


## Reads settings from a file. Returns "" when all was well (or there was no file yet),
## otherwise a sentence for the player naming the problem; unreadable values are replaced
## by their defaults (a damaged or unknown-version file: every value).
func load_file(path: String) -> String:
	reset_to_defaults()
	var read := IniText.read_file(path)
	if read.has("missing"):
		return ""
	if read.has("error"):
		return (
			"The settings file %s is damaged (%s), so the defaults are used."
			% [path, read["error"]]
		)
	var sections: Dictionary = read["sections"]
	var meta: Dictionary = sections.get("meta", {})
	var version: Variant = meta.get("version")
	var is_number := version is float or version is int
	var whole: int = version if is_number else 0
	if not is_number or whole != VERSION:
		return (
			"The settings file %s has an unknown version (%s), so the defaults are used."
			% [path, str(version)]
		)
	var problems := PackedStringArray()
	var audio: Dictionary = sections.get("audio", {})
	var display: Dictionary = sections.get("display", {})
	var controls: Dictionary = sections.get("controls", {})
	_read_number(audio, "master_volume", 0.0, 1.0, problems)
	_read_number(audio, "sfx_volume", 0.0, 1.0, problems)
	_read_flag(display, "fullscreen", problems)
	_read_flag(display, "show_frame_counter", problems)
	var progress: Dictionary = sections.get("progress", {})
	_read_flag(progress, "unlock_all_boards", problems)
	_read_number(controls, "tilt_sensitivity", MIN_TILT_SENSITIVITY, MAX_TILT_SENSITIVITY, problems)
	var input: Dictionary = sections.get("input", {})
	_read_bindings(input, problems)
	changed.emit()
	if problems.is_empty():
		return ""
	return (
		"Some settings in %s were unreadable and got their defaults: %s."
		% [path, ", ".join(problems)]
	)


func _read_number(
	section: Dictionary, key: String, low: float, high: float, problems: PackedStringArray
) -> void:
	if not section.has(key):
		return
	var value: Variant = section[key]
	if not (value is float or value is int):
		problems.append(key)
		return
	var number: float = value
	if not is_finite(number):
		problems.append(key)
		return
	if number < low or number > high:
		problems.append(key)
	set(key, clampf(number, low, high))


func _read_flag(section: Dictionary, key: String, problems: PackedStringArray) -> void:
	if not section.has(key):
		return
	if not section[key] is bool:
		problems.append(key)
		return
	set(key, section[key])


func _read_bindings(input: Dictionary, problems: PackedStringArray) -> void:
	for action: String in input:
		if not bindings.has(action):
			continue  # an action a later version removed: nothing to bind
		var codes: Variant = input[action]
		if not codes is Array:
			problems.append(action)
			continue
		var events: Array[InputEvent] = []
		var readable := true
		for code: Variant in codes:
			var event: InputEvent = Codec.decode(str(code)) if code is String else null
			if event == null:
				readable = false
				break
			events.append(event)
		if readable:
			bindings[action] = events
		else:
			problems.append(action)


func _apply_bus(bus_name: String, volume: float) -> void:
	var index := AudioServer.get_bus_index(bus_name)
	if index < 0:
		return
	AudioServer.set_bus_volume_db(index, linear_to_db(maxf(volume, 0.0001)))
	AudioServer.set_bus_mute(index, volume <= 0.0)
