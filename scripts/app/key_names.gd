class_name KeyNames
extends RefCounted
## The keys a player reads in on-screen help: the first keyboard key bound to an action, so
## the help stays true after the player remaps it (Settings → Controls).


## The first keyboard key bound to `action`, as the player would read it ("Space"), or
## `fallback` when the action has no key.
static func of(action: StringName, fallback: String = "") -> String:
	if not InputMap.has_action(action):
		return fallback
	for event in InputMap.action_get_events(action):
		var key := event as InputEventKey
		if key == null:
			continue
		# A physical key is named by its US-layout key, which is what the bindings store.
		var code := key.keycode if key.keycode != KEY_NONE else key.physical_keycode
		if code != KEY_NONE:
			return OS.get_keycode_string(code)
	return fallback
