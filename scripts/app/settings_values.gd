class_name SettingsValues
extends RefCounted
## Reads single values out of a settings file's sections, each checked on its own: a value
## that cannot be used is named in `problems` (the player's message lists them) and gives
## null, so GameSettings keeps its default. Pure: it knows no settings object.


## The number at `key` clamped to `low`..`high`; null when absent or not a finite number.
## Out of range is a problem too, and still gives the clamped number.
static func number(
	section: Dictionary, key: String, low: float, high: float, problems: PackedStringArray
) -> Variant:
	if not section.has(key):
		return null
	var value: Variant = section[key]
	if not (value is float or value is int):
		problems.append(key)
		return null
	var read: float = value
	if not is_finite(read):
		problems.append(key)
		return null
	if read < low or read > high:
		problems.append(key)
	return clampf(read, low, high)


## The true / false at `key`; null when absent or not a bool.
static func flag(section: Dictionary, key: String, problems: PackedStringArray) -> Variant:
	if not section.has(key):
		return null
	if not section[key] is bool:
		problems.append(key)
		return null
	return section[key]


## The remembered window size: both sides whole numbers of pixels from 0 (0 0: none yet) to
## `largest`; null when absent or not so (then a problem).
static func window_size(
	display: Dictionary, largest: float, problems: PackedStringArray
) -> Variant:
	var sides := Vector2i.ZERO
	for axis in 2:
		var key: String = ["window_width", "window_height"][axis]
		if not display.has(key):
			return null
		var value: Variant = display[key]
		var read: float = value if value is float or value is int else NAN
		if not is_finite(read) or read != floorf(read) or read < 0.0 or read > largest:
			problems.append(key)
			return null
		sides[axis] = int(read)
	return sides


## The events a list of binding codes names (at most `most`); empty when it is not such a
## list or one code is not a binding.
static func events(codes: Variant, most: int) -> Array[InputEvent]:
	var found: Array[InputEvent] = []
	if not codes is Array:
		return found
	var list: Array = codes
	if list.size() > most:
		return found
	for code: Variant in list:
		# a short code with short numbers: longer digit runs are not a key and overflow int()
		var sane := code is String and str(code).length() <= 40
		sane = sane and RegEx.create_from_string("\\d{10}").search(str(code)) == null
		var event: InputEvent = InputEventCodec.decode(str(code)) if sane else null
		if event == null:
			found.clear()
			return found
		found.append(event)
	return found
