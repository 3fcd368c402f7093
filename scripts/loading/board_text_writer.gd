class_name BoardTextWriter
extends RefCounted
## Writes a BoardLevel as `.board` text a person can review: JSON Lines, one field per
## line in a fixed order, then one item per line (a pin, a pocket, a wall, a start, a
## hole: each kind as its ItemKinds row writes it, in table order) in the board's order,
## coordinates rounded to 0.01 px, tuning one constant a line. A pocket's rim pins are not
## written: the pocket's line is the whole pocket, and the reader stamps its pins, so a
## pocket edit is a one-line diff. Adding a pin adds one line; deleting one removes one
## line (no commas between lines to shift). The same board always
## gives the same text, so a save that changes nothing writes nothing (BoardFormatSaver).

## Coordinates and sizes are written to this precision (px).
const PRECISION := LineText.PRECISION
## The lines of a board's text that name, describe or dress it (and the id counters and
## medal times) but never change how it plays: `play_text` leaves them out.
const NAMING_FIELDS: Array[String] = [
	"board_id", "display_name", "description", "fascia", "medal_times", BoardSchema.NEXT_IDS_FIELD
]


## SHA-256 of write(level): the same board gives the same hash however its file was laid
## out, and any edit changes it (replays, analysis results).
static func content_hash(level: BoardLevel) -> String:
	return write(level).sha256_text()


## The board's text without its naming lines (NAMING_FIELDS): what a play analysis depends
## on, so renaming a board or saving it under a new name keeps its analysis.
static func play_text(level: BoardLevel) -> String:
	var kept := PackedStringArray()
	for line in write(level).split("\n"):
		var named := NAMING_FIELDS.any(
			func(field: String) -> bool: return line.begins_with('{"%s": ' % field)
		)
		if not named:
			kept.append(line)
	return "\n".join(kept)


## SHA-256 of play_text(level): the key of a board's play analysis.
static func play_hash(level: BoardLevel) -> String:
	return play_text(level).sha256_text()


## The file text for `level`.
static func write(level: BoardLevel) -> String:
	var kind := BoardLevel.kind_name(level.kind)
	var lines := PackedStringArray()
	lines.append(
		(
			'{"format": %s, "format_version": %d}'
			% [JSON.stringify(BoardSchema.FORMAT), BoardSchema.FORMAT_VERSION]
		)
	)
	lines.append('{"kind": %s}' % JSON.stringify(kind))
	for field: String in BoardSchema.fields_for(kind):
		if field in ["format", "format_version", "kind"]:
			continue
		lines.append('{"%s": %s}' % [field, _value(level.get(field))])
	if level.is_maze():
		_append_medals(lines, level)
	else:
		lines.append('{"fascia": %s}' % JSON.stringify(level.fascia))
	lines.append_array(_tuning_lines(level.tuning))
	var counters := ItemIds.counters_to_save(level)
	if not counters.is_empty():
		lines.append('{"%s": %s}' % [BoardSchema.NEXT_IDS_FIELD, _counters(counters)])
	for row in ItemKinds.of_game(level.kind):
		_append_items(lines, level, row)
	return "\n".join(lines) + "\n"


## `number` rounded to PRECISION, written without trailing zeros ("12", "12.5", "-0.25"):
## the way every number of an item line is written too (LineText).
static func number(value: float) -> String:
	return LineText.number(value)


static func _value(value: Variant) -> String:
	if value is Vector2:
		var v: Vector2 = value
		return "[%s, %s]" % [number(v.x), number(v.y)]
	if value is float:
		var real: float = value
		return number(real)
	return JSON.stringify(value)


# One line per tuning constant, in name order (`{"tuning": {"gravity": [0, 777.7778]}}`), so
# changing one is a one-line diff. Values keep their full precision in the fewest digits that
# read back to the same number: they come from formulas (0.7 / 0.03²), and rounding them
# would change how every board plays.
static func _tuning_lines(tuning: PhysicsTuning) -> PackedStringArray:
	var lines := PackedStringArray()
	var source := tuning if tuning != null else PhysicsTuning.new()
	var names := BoardRanges.tuning_fields().keys()
	names.sort()
	for name: String in names:
		var value: Variant = source.get(name)
		if name in BoardRanges.TUNING_WRITTEN_WHEN_SET and value == 0.0:
			continue
		var text := ""
		if value is Vector2:
			var v: Vector2 = value
			text = "[%s, %s]" % [_shortest_single(v.x), _shortest_single(v.y)]
		elif value is float:
			var real: float = value
			text = _shortest(real)
		else:
			text = JSON.stringify(value)
		lines.append('{"tuning": {"%s": %s}}' % [name, text])
	return lines


# `{"pins": 626, "walls": 40}` in ItemIds.lists() order, so the same board gives the same text.
static func _counters(counters: Dictionary[String, int]) -> String:
	var parts := PackedStringArray()
	for list in ItemIds.lists():
		if counters.has(list):
			parts.append('"%s": %d' % [list, counters[list]])
	return "{" + ", ".join(parts) + "}"


# The fewest digits that read back to exactly `value` (a 64-bit float).
static func _shortest(value: float) -> String:
	if value == floorf(value) and absf(value) < 1e15:
		return str(int(value))
	return String.num_scientific(value)


# The fewest decimals that read back to `value` once stored in 32 bits, as a Vector2's
# components are (777.7778, not 777.7777709960938).
static func _shortest_single(value: float) -> String:
	if value == floorf(value) and absf(value) < 1e15:
		return str(int(value))
	for decimals in range(1, 13):
		var text := String.num(value, decimals)
		if Vector2(text.to_float(), 0.0).x == value:
			return text
	return _shortest(value)


# The optional medal times line, only for a board that has some.
static func _append_medals(lines: PackedStringArray, level: BoardLevel) -> void:
	var parts := PackedStringArray()
	for mode in BoardSchema.MEDAL_MODES:
		var times: PackedFloat64Array = (
			level.medal_times_easy if mode == "easy" else level.medal_times_hard
		)
		if times.size() == 3:
			parts.append(
				'"%s": [%s, %s, %s]' % [mode, number(times[0]), number(times[1]), number(times[2])]
			)
	if not parts.is_empty():
		lines.append('{"medal_times": {%s}}' % ", ".join(parts))


# One line per item of `kind`, in board order, each starting with its stable id:
# `{"pin": {"id": 17, "x": 255, "y": 84}}`. Entries that are not items of their own (a
# pocket's rim pins, stamped from the pocket line) are not written. A board without items
# of a kind gets no line, so older boards keep their exact text.
static func _append_items(lines: PackedStringArray, level: BoardLevel, kind: ItemKind) -> void:
	var indices := kind.field_indices(level)
	for place in indices.size():
		var index := indices[place]
		if not kind.is_item(level, index):
			continue
		var id := ItemIds.of(level, kind.list, place)
		lines.append('{"%s": {"id": %d, %s}}' % [kind.name, id, kind.line_of(level, index)])
