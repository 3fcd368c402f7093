class_name BoardTextBuilder
extends RefCounted
## Builds a BoardLevel from a board file's gathered and checked fields (BoardTextReader
## reads and checks; this makes the level): fields set by name, the tuning, then each item
## kind's lines as its ItemKinds row reads them (pins, pockets with their stamped rims, the
## bonus layer, windmills; walls, ball starts, holes).


## The BoardLevel `data` describes. `data` must have passed BoardTextReader's checks (kind,
## fields, items, tuning): this trusts every value's type and range.
static func build(data: Dictionary) -> BoardLevel:
	var level := BoardLevel.new()
	var kind: String = data["kind"]
	level.kind = BoardLevel.kind_named(kind) as BoardLevel.Kind
	for field: String in BoardSchema.fields_for(kind):
		if field in ["format", "format_version", "kind"]:
			continue
		level.set(field, _value_for(level.get(field), data[field]))
	var tuning: Dictionary = data.get("tuning", {})
	level.tuning = _build_tuning(level, tuning)
	# Each kind's lines, in table order: pins before the pockets that stamp theirs after them.
	for row in ItemKinds.of_game(level.kind):
		var lines: Array = data.get(row.list, [])
		data[row.list] = row.read_lines(level, lines)  # the ids read below are these lines'
	if level.is_pachinko():
		level.fascia = str(data.get("fascia", FasciaNames.CLASSIC))
	else:
		var medals: Dictionary = data.get("medal_times", {})
		var easy: Array = medals.get("easy", [])
		var hard: Array = medals.get("hard", [])
		level.medal_times_easy = _times(easy)
		level.medal_times_hard = _times(hard)
	var counters: Dictionary = data.get(BoardSchema.NEXT_IDS_FIELD, {})
	var next_ids: Dictionary[String, int] = {}
	for list: Variant in counters:
		next_ids[str(list)] = int_of(counters[list])
	level.next_ids = next_ids
	for row in ItemKinds.listed():
		var ids := PackedInt32Array()
		for item: Dictionary in data.get(row.list, []):
			ids.append(int_of(item.get("id", 0)))
		level.set(row.id_field, ids)
	ItemIds.fill(level)  # missing or repeated ids get fresh numbers
	return level


# A field takes the JSON value in the type the BoardLevel property has.
static func _value_for(current: Variant, value: Variant) -> Variant:
	if current is Vector2:
		var pair: Array = value
		return Vector2(float_of(pair[0]), float_of(pair[1]))
	if current is int:
		return int_of(value)
	if current is float:
		return float_of(value)
	return value


static func _build_tuning(level: BoardLevel, values: Dictionary) -> PhysicsTuning:
	var tuning := TuningPresets.for_kind(level.is_maze())
	for key: String in values:
		# An old name is stored under its new one (the check already let it through so).
		var field: String = BoardSchema.RENAMED_TUNING.get(key, key)
		tuning.set(field, _value_for(tuning.get(field), values[key]))
	return tuning


static func _times(values: Array) -> PackedFloat64Array:
	var times := PackedFloat64Array()
	for value: Variant in values:
		times.append(float_of(value))
	return times


## A checked JSON number as a float (typed, so no unsafe conversion warning).
static func float_of(value: Variant) -> float:
	var number: float = value
	return number


## A checked JSON number as an int (a float is cut toward zero, as int() does).
static func int_of(value: Variant) -> int:
	var whole: int = value
	return whole
