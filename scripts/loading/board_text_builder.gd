extends RefCounted
## Builds a BoardLevel from a board file's gathered and checked fields (BoardTextReader
## reads and checks; this makes the level): fields set by name, pins, pockets with their
## stamped rims, the bonus layer, windmills and the tuning.

const Schema := preload("res://scripts/loading/board_schema.gd")


## The BoardLevel `data` describes. `data` must have passed BoardTextReader's checks (kind,
## fields, items, tuning): this trusts every value's type and range.
static func build(data: Dictionary) -> BoardLevel:
	var level := BoardLevel.new()
	var kind: String = data["kind"]
	level.kind = BoardLevel.kind_named(kind) as BoardLevel.Kind
	for field: String in Schema.fields_for(kind):
		if field in ["format", "format_version", "kind"]:
			continue
		level.set(field, _value_for(level.get(field), data[field]))
	var tuning: Dictionary = data.get("tuning", {})
	level.tuning = _build_tuning(level, tuning)
	if level.is_pachinko():
		level.fascia = str(data.get("fascia", FasciaNames.CLASSIC))
		# Files before rim pins were derived stored each pocket's pins (`"pocket": k`): the
		# pocket line is the truth, so those are dropped and every pocket stamps its own.
		var stored: Array = data.get("pins", [])
		var pins := _field_pins(stored)
		data["pins"] = pins  # the ids read below are the field pins' only
		var pockets: Array = data.get("pockets", [])
		_build_pins(level, pins)
		_build_pockets(level, pockets)
		for k in level.pockets.size():
			PocketStamp.apply(level, k)
		_build_bonus(level, data)
		var wheels: Array = data.get("windmills", [])
		_build_windmills(level, wheels)
	else:
		var walls: Array = data.get("walls", [])
		var ball_starts: Array = data.get("ball_starts", [])
		var holes: Array = data.get("holes", [])
		level.walls = _points(walls, ["ax", "ay", "bx", "by"])
		level.ball_starts = _points(ball_starts, ["x", "y"])
		level.holes = _points(holes, ["x", "y"])
		var medals: Dictionary = data.get("medal_times", {})
		var easy: Array = medals.get("easy", [])
		var hard: Array = medals.get("hard", [])
		level.medal_times_easy = _times(easy)
		level.medal_times_hard = _times(hard)
	var counters: Dictionary = data.get(Schema.NEXT_IDS_FIELD, {})
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
		var field: String = Schema.RENAMED_TUNING.get(key, key)
		tuning.set(field, _value_for(tuning.get(field), values[key]))
	return tuning


static func _field_pins(items: Array) -> Array:
	var kept: Array = []
	for item: Dictionary in items:
		if not item.has("pocket"):
			kept.append(item)
	return kept


static func _build_pins(level: BoardLevel, items: Array) -> void:
	var pins := PackedVector2Array()
	var pockets := PackedInt32Array()
	var special := PackedByteArray()
	for item: Dictionary in items:
		pins.append(Vector2(float_of(item["x"]), float_of(item["y"])))
		pockets.append(-1)
		special.append(1 if item.get("special", false) else 0)
	level.pins = pins
	level.pin_pocket = pockets
	level.pin_special = special


static func _build_pockets(level: BoardLevel, items: Array) -> void:
	var specs: Array[PocketSpec] = []
	for item: Dictionary in items:
		var at := Vector2(float_of(item["x"]), float_of(item["y"]))
		var width := float_of(item["width"])
		var depth := float_of(item["depth"])
		specs.append(PocketSpec.create(at, width, depth, int_of(item["payout"])))
	level.pockets = specs


# The bonus lists, in role order (start pockets, attackers, tulips).
static func _build_bonus(level: BoardLevel, data: Dictionary) -> void:
	var specs: Array[BonusPocketSpec] = []
	for role in Schema.BONUS_LISTS.size():
		var items: Array = data.get(Schema.BONUS_LISTS[role], [])
		for item: Dictionary in items:
			var at := Vector2(float_of(item["x"]), float_of(item["y"]))
			var spec := BonusPocketSpec.of_role(
				role, at, float_of(item["width"]), float_of(item["depth"]), int_of(item["payout"])
			)
			spec.symbols = int_of(item.get("symbols", BonusPocketSpec.DEFAULT_SYMBOLS))
			spec.open_seconds = float_of(
				item.get("open_seconds", BonusPocketSpec.DEFAULT_OPEN_SECONDS)
			)
			spec.open_catches = int_of(
				item.get("open_catches", BonusPocketSpec.DEFAULT_OPEN_CATCHES)
			)
			specs.append(spec)
	level.bonus_pockets = specs


static func _build_windmills(level: BoardLevel, items: Array) -> void:
	var specs: Array[WindmillSpec] = []
	for item: Dictionary in items:
		var at := Vector2(float_of(item["x"]), float_of(item["y"]))
		var blades := int_of(item["blades"])
		var length := float_of(item["length"])
		if item.has("friction"):
			specs.append(WindmillSpec.spinning_free(at, blades, length, float_of(item["friction"])))
		else:
			specs.append(WindmillSpec.driven(at, blades, length, float_of(item["speed"])))
	level.windmills = specs


static func _points(items: Array, keys: Array[String]) -> PackedVector2Array:
	var points := PackedVector2Array()
	for item: Dictionary in items:
		for i: int in range(0, keys.size(), 2):
			points.append(Vector2(float_of(item[keys[i]]), float_of(item[keys[i + 1]])))
	return points


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
