class_name BindingMoves
extends RefCounted
## Bindings that clash: a key or button already bound to another action that can fire in the
## same game (two maze actions, two pachinko ones, or a general action and either game's).
## The shipped controls share some on purpose (Space launches in pachinko and resets the
## maze; the gamepad's A both launches and starts a game): a pair the defaults give one
## event to is never a clash. Moving a binding takes it off the other actions; one left with
## no binding of that kind gets the moved-to action's old one instead (a swap), and a move
## that would leave an action with none is refused, so no action is ever left unbound.


## The game an action belongs to (a name of BoardLevel.KIND_NAMES), or "" for the general
## ones.
static func game_of(action: String) -> String:
	if action.begins_with("tilt_") or action.begins_with("maze_"):
		return BoardLevel.MAZE_NAME
	if action.begins_with("launch_") or action.begins_with("handle_"):
		return BoardLevel.PACHINKO_NAME
	return ""


## The other actions of `settings` that `event` would also fire if it were bound to
## `action` (in the settings' action order).
static func clashes(settings: GameSettings, action: String, event: InputEvent) -> PackedStringArray:
	var code := InputEventCodec.encode(event)
	var found := PackedStringArray()
	if code.is_empty():
		return found
	var defaults := GameSettings.default_bindings()
	for other: String in settings.bindings:
		if other == action or not _share_a_game(action, other):
			continue
		if (
			_has_code(settings.events_for(other), code)
			and not _shipped_together(defaults, action, other, code)
		):
			found.append(other)
	return found


## What moving `event` to `action`'s keyboard (gamepad false) or gamepad column would do:
## {"ok": true, "swaps": {other action: the event it gets instead}} or {"ok": false,
## "stuck": the action that would be left with no binding of that kind}.
static func plan(
	settings: GameSettings, action: String, event: InputEvent, gamepad: bool
) -> Dictionary:
	var giving_back: InputEvent = null
	for old: InputEvent in settings.events_for(action):
		if (
			InputEventCodec.is_gamepad(old) == gamepad
			and InputEventCodec.encode(old) != InputEventCodec.encode(event)
		):
			giving_back = old
			break
	var swaps := {}
	var code := InputEventCodec.encode(event)
	for other in clashes(settings, action, event):
		var left := 0
		for kept: InputEvent in settings.events_for(other):
			if InputEventCodec.is_gamepad(kept) == gamepad and InputEventCodec.encode(kept) != code:
				left += 1
		if left > 0:
			continue
		if giving_back == null:
			return {"ok": false, "stuck": other}
		swaps[other] = giving_back
	return {"ok": true, "swaps": swaps}


## Binds `event` to `action`'s column, takes it off every clashing action and gives the ones
## left empty their swap (see `plan`). Returns the plan; nothing changes when it is not ok.
static func move(
	settings: GameSettings, action: String, event: InputEvent, gamepad: bool
) -> Dictionary:
	var result := plan(settings, action, event, gamepad)
	if not result["ok"]:
		return result
	var code := InputEventCodec.encode(event)
	var swaps: Dictionary = result["swaps"]
	for other in clashes(settings, action, event):
		var events: Array[InputEvent] = []
		for kept: InputEvent in settings.events_for(other):
			if InputEventCodec.encode(kept) != code:
				events.append(kept)
		if swaps.has(other):
			var swapped: InputEvent = swaps[other]
			events.append(swapped.duplicate() as InputEvent)
		settings.bindings[other] = events
	settings.rebind(action, event, gamepad)
	return result


static func _share_a_game(a: String, b: String) -> bool:
	var game_a := game_of(a)
	var game_b := game_of(b)
	return game_a == game_b or game_a.is_empty() or game_b.is_empty()


static func _has_code(events: Array[InputEvent], code: String) -> bool:
	for event in events:
		if InputEventCodec.encode(event) == code:
			return true
	return false


static func _shipped_together(defaults: Dictionary, a: String, b: String, code: String) -> bool:
	var listed_a: Array = defaults.get(a, [])
	var listed_b: Array = defaults.get(b, [])
	var shipped_a: Array[InputEvent] = []
	shipped_a.assign(listed_a)
	var shipped_b: Array[InputEvent] = []
	shipped_b.assign(listed_b)
	return _has_code(shipped_a, code) and _has_code(shipped_b, code)
