class_name GameSettings
extends RefCounted
## The player's settings: volumes (master, effects, music), window mode, frame counter, tilt
## sensitivity and the key and gamepad bindings of every game action. Saved as a readable INI file
## (user://settings.cfg). `load_file` reads it as data and validates every value: an
## unreadable value gets its default, a damaged file is moved aside (kept for the player) and
## the defaults are used, a file from a newer version is left untouched and never saved over.
## Either way it names the problem in one sentence and never stops the game.

## Emitted after any value changed through a setter or a load.
signal changed

const VERSION := 1
const DEFAULT_MUSIC_VOLUME := 0.6
const MIN_TILT_SENSITIVITY := 0.25
const MAX_TILT_SENSITIVITY := 3.0
## Actions that must keep a keyboard and a gamepad binding: without one, a player on that
## device has no way out of a game.
const REQUIRED_ACTIONS: Array[String] = ["pause"]
## More bindings than this on one action is not a file a person wrote.
const MAX_BINDINGS_PER_ACTION := 16
## A remembered window side past this many pixels is not one a screen has.
const MAX_WINDOW_SIDE := 16384.0
const FILE_HEADER := (
	"Board Studio settings (format version %d). Delete this file to restore the defaults.\n"
	+ "Bindings: key:<name>, joy_button:<index>, joy_axis:<index>:<+|->, mouse:<index>."
)
## What the player is told about a settings file that could not be used (PlayerFileLoad).
const LOAD_WORDS := {
	"damaged": "%s could not be read (%s), so the defaults are used.",
	"newer":
	(
		"%s is from a newer version of Board Studio (format %d): the defaults are used, "
		+ "and the file is left as it is (changes are not saved)."
	),
	"partly": "Some settings in %s could not be used and got their defaults: %s.",
}

## Master volume, 0 (silent) to 1 (full).
var master_volume := 1.0
## Sound effects volume, 0 to 1.
var sfx_volume := 1.0
## Music volume, 0 to 1: under the effects by default, so the machine's tune sits behind the
## balls rather than over them.
var music_volume := DEFAULT_MUSIC_VOLUME
## Fullscreen when true, a window when false.
var fullscreen := false
## Show the frames-per-second counter in a corner.
var show_frame_counter := false
## Show the ghost of the best maze run on the board and mode.
var show_ghost := true
## Draw the tilt maze in the tutorial's flat colours instead of wood and steel.
var maze_tutorial_look := false
## Low graphics for the tilt maze: no soft shadows, no wood grain, no reflections, for
## machines that draw 3D without a graphics card (software GL).
var maze_low_graphics := false
## Multiplier on the maze tilt from keys and sticks.
var tilt_sensitivity := 1.0
## Every maze board open from the start, instead of one after another.
var unlock_all_boards := false
## Gamepad rumble and phone vibration when a maze ball knocks a wall or drops into a hole.
var vibration := true
## The pachinko board jolts on a jackpot (off for players whom screen motion troubles).
var screen_shake := true
## The window size the player left the game at (Vector2i.ZERO: none yet, fit the screen).
var window_size := Vector2i.ZERO
## Action name -> Array of InputEvent, for every action in `remappable_actions()`.
var bindings := {}

# a file from a newer version, loaded as defaults: never written over during this run
var _untouchable_path := ""


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
	music_volume = DEFAULT_MUSIC_VOLUME
	fullscreen = false
	show_frame_counter = false
	show_ghost = true
	maze_tutorial_look = false
	maze_low_graphics = false
	tilt_sensitivity = 1.0
	unlock_all_boards = false
	vibration = true
	screen_shake = true
	window_size = Vector2i.ZERO
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
		if InputEventCodec.is_gamepad(old) != gamepad:
			events.append(old)
	events.append(event)
	bindings[action] = events
	changed.emit()


## Removes the keyboard (gamepad = false) or gamepad events of an action. A column of an
## action in [constant REQUIRED_ACTIONS] is never left empty: its shipped bindings come back
## instead. Returns false when that happened.
func clear_binding(action: String, gamepad: bool) -> bool:
	if not bindings.has(action):
		push_error("GameSettings.clear_binding: unknown action '%s'" % action)
		return false
	var events: Array[InputEvent] = []
	for old: InputEvent in bindings[action]:
		if InputEventCodec.is_gamepad(old) != gamepad:
			events.append(old)
	var kept := _with_required_columns(action, events)
	bindings[action] = kept
	changed.emit()
	return kept.size() == events.size()


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
		"music_volume":
			var volume: float = value
			music_volume = clampf(volume, 0.0, 1.0)
		"fullscreen":
			var on: bool = value
			fullscreen = on
		"show_frame_counter", "show_ghost", "unlock_all_boards":
			var on: bool = value
			set(key, on)
		"maze_tutorial_look", "maze_low_graphics":
			var on: bool = value
			set(key, on)
		"screen_shake":
			var on: bool = value
			screen_shake = on
		"tilt_sensitivity":
			var sensitivity: float = value
			tilt_sensitivity = clampf(sensitivity, MIN_TILT_SENSITIVITY, MAX_TILT_SENSITIVITY)
		"vibration":
			var on: bool = value
			vibration = on
		_:
			push_error("GameSettings.set_value: unknown setting '%s'" % key)
			return
	changed.emit()


## Pushes the values into the engine: bus volumes, window mode, the InputMap.
func apply() -> void:
	_apply_bus("Master", master_volume)
	_apply_bus("SFX", sfx_volume)
	_apply_bus("Music", music_volume)
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


## Writes the settings as readable text. Returns OK or the file error; a file from a newer
## version that `load_file` read is never written over (ERR_FILE_NO_PERMISSION, no write).
func save_file(path: String) -> Error:
	if not _untouchable_path.is_empty() and path == _untouchable_path:
		return ERR_FILE_NO_PERMISSION
	var input := {}
	for action: String in bindings:
		var codes: Array[String] = []
		for event: InputEvent in bindings[action]:
			var code := InputEventCodec.encode(event)
			if not code.is_empty():
				codes.append(code)
		input[action] = codes
	var sections := [
		["meta", {"version": VERSION}],
		[
			"audio",
			{
				"master_volume": master_volume,
				"sfx_volume": sfx_volume,
				"music_volume": music_volume,
			}
		],
		[
			"display",
			{
				"fullscreen": fullscreen,
				"show_frame_counter": show_frame_counter,
				"show_ghost": show_ghost,
				"maze_tutorial_look": maze_tutorial_look,
				"maze_low_graphics": maze_low_graphics,
				"screen_shake": screen_shake,
				"window_width": window_size.x,
				"window_height": window_size.y,
			}
		],
		["controls", {"tilt_sensitivity": tilt_sensitivity, "vibration": vibration}],
		["progress", {"unlock_all_boards": unlock_all_boards}],
		["input", input],
	]
	var error := IniText.write_file(path, IniText.format(FILE_HEADER % VERSION, sections))
	if error != OK:
		push_error("Could not save settings to %s: %s" % [path, error_string(error)])
	return error


## Reads settings from a file. Returns "" when all was well (or there was no file yet),
## otherwise a sentence for the player naming the problem and where the old file went.
## Values that cannot be used get their defaults one by one; a file that is not readable
## text, or has no usable version, is moved aside and every value gets its default.
func load_file(path: String) -> String:
	reset_to_defaults()
	var loaded := PlayerFileLoad.run(path, VERSION, _take_values, LOAD_WORDS)
	_untouchable_path = path if loaded.untouchable else ""
	return loaded.message


func _take_values(sections: Dictionary, _version: int) -> PackedStringArray:
	var problems := _read_values(sections)
	changed.emit()
	return problems


# Takes every known value it can use from the sections; returns the keys it could not use.
func _read_values(sections: Dictionary) -> PackedStringArray:
	var problems := PackedStringArray()
	var audio: Dictionary = sections.get("audio", {})
	var display: Dictionary = sections.get("display", {})
	var controls: Dictionary = sections.get("controls", {})
	_read_number(audio, "master_volume", 0.0, 1.0, problems)
	_read_number(audio, "sfx_volume", 0.0, 1.0, problems)
	_read_number(audio, "music_volume", 0.0, 1.0, problems)
	_read_flag(display, "fullscreen", problems)
	_read_flag(display, "show_frame_counter", problems)
	_read_flag(display, "show_ghost", problems)
	_read_flag(display, "maze_tutorial_look", problems)
	_read_flag(display, "maze_low_graphics", problems)
	_read_flag(display, "screen_shake", problems)
	_read_window_size(display, problems)
	_read_number(controls, "tilt_sensitivity", MIN_TILT_SENSITIVITY, MAX_TILT_SENSITIVITY, problems)
	_read_flag(controls, "vibration", problems)
	var progress: Dictionary = sections.get("progress", {})
	_read_flag(progress, "unlock_all_boards", problems)
	var input: Dictionary = sections.get("input", {})
	_read_bindings(input, problems)
	return problems


func _read_number(
	section: Dictionary, key: String, low: float, high: float, problems: PackedStringArray
) -> void:
	var read: Variant = SettingsValues.number(section, key, low, high, problems)
	if read != null:
		set(key, read)


func _read_window_size(display: Dictionary, problems: PackedStringArray) -> void:
	var read: Variant = SettingsValues.window_size(display, MAX_WINDOW_SIDE, problems)
	if read != null:
		window_size = read


func _read_flag(section: Dictionary, key: String, problems: PackedStringArray) -> void:
	var read: Variant = SettingsValues.flag(section, key, problems)
	if read != null:
		set(key, read)


func _read_bindings(input: Dictionary, problems: PackedStringArray) -> void:
	for action: String in input:
		if not bindings.has(action):
			continue  # an action a later version removed: nothing to bind
		var codes: Variant = input[action]
		var events := SettingsValues.events(codes, MAX_BINDINGS_PER_ACTION)
		if events.is_empty() and REQUIRED_ACTIONS.has(action):
			problems.append("%s (it needs a binding)" % action)
		elif events.is_empty() and not (codes is Array and codes == []):
			problems.append(action)
		else:
			bindings[action] = _with_required_columns(action, events)


# `events` with the shipped keyboard or gamepad bindings added for a required action that
# has none of that kind.
func _with_required_columns(action: String, events: Array[InputEvent]) -> Array[InputEvent]:
	if not REQUIRED_ACTIONS.has(action):
		return events
	var result := events.duplicate()
	for gamepad: bool in [false, true]:
		if events.any(
			func(event: InputEvent) -> bool: return InputEventCodec.is_gamepad(event) == gamepad
		):
			continue
		for shipped: InputEvent in default_bindings().get(action, []):
			if InputEventCodec.is_gamepad(shipped) == gamepad:
				result.append(shipped)
	return result


func _apply_bus(bus_name: String, volume: float) -> void:
	var index := AudioServer.get_bus_index(bus_name)
	if index < 0:
		return
	AudioServer.set_bus_volume_db(index, linear_to_db(maxf(volume, 0.0001)))
	AudioServer.set_bus_mute(index, volume <= 0.0)
