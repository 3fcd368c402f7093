class_name BoardSchema
extends RefCounted
## The board file's schema: every field a `.board` file may hold, its type and its range,
## and the item lists with their counts. `BoardTextReader` checks a parsed file against it
## before any BoardLevel exists, so a value that would break the world is refused with the
## field named. The ranges are generous for designers and tight enough that no board can
## freeze the game, exhaust memory or turn a ball's numbers into NaN.

## The value of the file's "format" key.
const FORMAT := "board-studio-board"
## The file layout this code writes; a newer number is refused, never guessed at.
const FORMAT_VERSION := 1
## A board file larger than this is refused before it is parsed.
const MAX_FILE_BYTES := 2 * 1024 * 1024
## Coordinates (board pixels) may not leave this square around the origin.
const MAX_COORD := 10000.0

## Field name → [type, min, max]. Types: "int", "float", "vec2", "string", "kind".
const COMMON := {
	"format": ["string", 0, 64],
	"format_version": ["int", 1, FORMAT_VERSION],
	"kind": ["kind", 0, 0],
	"board_id": ["string", 1, 64],
	"display_name": ["string", 1, 80],
	"description": ["string", 0, 600],
	"size": ["vec2", 1.0, 4096.0],
	"ball_radius": ["float", 0.5, 100.0],
}
const PACHINKO := {
	"ring_center": ["vec2", -MAX_COORD, MAX_COORD],
	"ring_radius": ["float", 10.0, 2048.0],
	"rail_width": ["float", 0.0, 500.0],
	"rail_start_deg": ["float", -720.0, 720.0],
	"rail_end_deg": ["float", -720.0, 720.0],
	"gutter_start_deg": ["float", -720.0, 720.0],
	"gutter_end_deg": ["float", -720.0, 720.0],
	"gutter_bounces": ["int", 1, 100],
	"pin_radius": ["float", 0.0, 100.0],
	"cup_start_balls": ["int", 0, 100000],
}
const MAZE := {
	"grid_cols": ["int", 1, 64],
	"grid_rows": ["int", 1, 64],
	"path_width": ["float", 1.0, 1000.0],
	"wall_width": ["float", 0.0, 1000.0],
	"goal_center": ["vec2", -MAX_COORD, MAX_COORD],
	"goal_radius": ["float", 1.0, 2048.0],
	"hole_radius": ["float", 0.0, 500.0],
}
## Fields a pachinko file may leave out: the machine it is dressed as (FasciaNames; classic
## when missing, so files from before machines had names still load).
const PACHINKO_OPTIONAL := {"fascia": ["fascia", 0, 0]}
## Fields a maze file may leave out: medal times per mode,
## `{"medal_times": {"easy": [gold, silver, bronze], "hard": [...]}}` in seconds.
const MAZE_OPTIONAL := {"medal_times": ["medals", 0.1, 36000.0]}
## The modes medal times are given for.
const MEDAL_MODES: Array[String] = ["easy", "hard"]
## The item lines, their lists, counts and fields are each kind's ItemKinds row's
## (`max_items`, `file_fields`, `optional_file_fields`).

## The optional header field holding the id counters: `{"next_ids": {"pins": 626}}`, list
## name -> the id its next new item gets (BoardLevel.next_ids). Written only for a list whose
## counter is past its largest id + 1; a counter at or below an id in use is raised on load.
const NEXT_IDS_FIELD := "next_ids"
## The range of one counter.
const NEXT_ID_SPEC := ["int", 1, ItemIds.MAX_ID + 1]
## A file may not have more lines than this (every list full, plus the fields).
const MAX_LINES := 12000
## Old names of tuning fields a file may still use (read as the new name, never written).
const RENAMED_TUNING := {"gutter_slide_time": "drain_slide_time"}


## The top-level fields a board of `kind_name` (BoardLevel.KIND_NAMES) must have.
static func fields_for(kind_name: String) -> Dictionary:
	var fields := COMMON.duplicate()
	fields.merge(MAZE if kind_name == BoardLevel.MAZE_NAME else PACHINKO)
	return fields


## The top-level fields a board of `kind_name` may leave out.
static func optional_fields_for(kind_name: String) -> Dictionary:
	return MAZE_OPTIONAL if kind_name == BoardLevel.MAZE_NAME else PACHINKO_OPTIONAL


## The item lists a board of `kind_name` has, in file order (ItemKinds).
static func lists_for(kind_name: String) -> Array[String]:
	var maze := kind_name == BoardLevel.MAZE_NAME
	var lists: Array[String] = []
	for kind in ItemKinds.of_game(BoardLevel.Kind.MAZE if maze else BoardLevel.Kind.PACHINKO):
		lists.append(kind.list)
	return lists


## The list an item line keyed `key` goes to (`{"pin": {...}}` to "pins"), or "".
static func list_of_key(key: Variant) -> String:
	var kind := ItemKinds.of_name(str(key)) if key is String else null
	return kind.list if kind != null and not kind.file_fields.is_empty() else ""


## True when `name` is an item list ("pins"): its items go one a line, never as a list.
static func is_list(name: Variant) -> bool:
	var kind := ItemKinds.of_list(str(name)) if name is String else null
	return kind != null and not kind.file_fields.is_empty()


## The most items `list` may hold.
static func most_items(list: String) -> int:
	return ItemKinds.of_list(list).max_items


## The fields an item line of `list` must have: field -> [type, min, max] (check_value).
static func item_fields(list: String) -> Dictionary:
	return ItemKinds.of_list(list).file_fields


## The fields an item line of `list` may leave out (its id first).
static func optional_item_fields(list: String) -> Dictionary:
	return ItemKinds.of_list(list).optional_file_fields


## "" when `value` fits `spec` ([type, min, max]), else what is wrong with it.
static func check_value(value: Variant, spec: Array) -> String:
	var type: String = spec[0]
	match type:
		"coord":
			return check_value(value, ["float", -MAX_COORD, MAX_COORD])
		"bool":
			return "" if value is bool else "must be true or false"
		"fascia":
			if FasciaNames.is_known(value):
				return ""
			return (
				"names no machine this game has (%s): pick %s"
				% [JSON.stringify(value), FasciaNames.choices()]
			)
		"kind":
			return (
				"" if BoardLevel.kind_named(value) >= 0 else "must be " + BoardLevel.kind_choices()
			)
		"string":
			if not value is String:
				return "must be a text in quotes"
			var text: String = value
			var shortest: int = spec[1]
			var longest: int = spec[2]
			if text.length() < shortest or text.length() > longest:
				return "must be %d to %d characters long" % [spec[1], spec[2]]
			return ""
		"vec2":
			var pair: Array = value if value is Array else []
			if pair.size() != 2:
				return "must be a pair of numbers [x, y]"
			var problem := check_number(pair[0], _bound(spec, 1), _bound(spec, 2), false)
			return (
				problem
				if not problem.is_empty()
				else (check_number(pair[1], _bound(spec, 1), _bound(spec, 2), false))
			)
		"int":
			return check_number(value, _bound(spec, 1), _bound(spec, 2), true)
		"medals":
			return _check_medals(value, _bound(spec, 1), _bound(spec, 2))

	return check_number(value, _bound(spec, 1), _bound(spec, 2), false)


## "" when `value` is a finite number in [low, high] (a whole one when `whole`).
static func check_number(value: Variant, low: float, high: float, whole: bool) -> String:
	if not (value is float or value is int):
		return "must be a number"
	var number: float = value
	if is_nan(number) or is_inf(number):
		return "must be a finite number"
	if whole and number != floorf(number):
		return "must be a whole number"
	if number < low or number > high:
		return "must be between %s and %s, got %s" % [_short(low), _short(high), _short(number)]
	return ""


# Medal times: {"easy": [gold, silver, bronze], "hard": [...]}, each mode optional, each
# time in [low, high] and no faster than the medal above it.
static func _check_medals(value: Variant, low: float, high: float) -> String:
	if not value is Dictionary:
		return 'must be an object {"easy": [gold, silver, bronze], "hard": [...]}'
	var modes: Dictionary = value
	for mode: Variant in modes.keys():
		if not mode in MEDAL_MODES:
			return 'has an unknown mode "%s" (only "easy" and "hard")' % mode
		var times: Array = modes[mode] if modes[mode] is Array else []
		if times.size() != 3:
			return '"%s" must be three times [gold, silver, bronze] in seconds' % mode
		for i in 3:
			var problem := check_number(times[i], low, high, false)
			if not problem.is_empty():
				return '"%s" %s' % [mode, problem]
			if i > 0 and _float(times[i]) < _float(times[i - 1]):
				return '"%s" times must not get faster from gold to bronze' % mode
	return ""


static func _float(value: Variant) -> float:
	var number: float = value
	return number


# The number at `index` of a spec ([type, min, max]) as a float.
static func _bound(spec: Array, index: int) -> float:
	var bound: float = spec[index]
	return bound


static func _short(number: float) -> String:
	if absf(number) >= 1e9:
		return String.num_scientific(number)
	return str(int(number)) if number == floorf(number) else str(number)
