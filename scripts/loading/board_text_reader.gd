class_name BoardTextReader
extends RefCounted
## Reads a `.board` file's text into a BoardLevel. A board file is JSON Lines: every line is
## one JSON object, either fields (`{"ring_radius": 320}`) or one item
## (`{"pin": {"x": 120, "y": 300}}`), so adding a pin adds exactly one line. Each line goes
## to Godot's JSON parser, which can only make plain values (numbers, strings, arrays,
## dictionaries) and refuses NaN and structures nested too deep; every field is then checked
## against BoardSchema (type, range, finiteness, counts, no unknown or repeated keys) before
## a BoardLevel is built in code. Nothing in a board file can name a script, a class or
## another file.

## Top-level fields besides the kind's own (board_schema.gd) and its item lists.
const OTHER_FIELDS: Array[String] = ["tuning", BoardSchema.NEXT_IDS_FIELD]


## Like read(), from the file's raw bytes. A NUL byte is refused here, before decoding,
## because a Godot String cannot hold one: decoding would silently turn it into U+FFFD.
static func read_bytes(bytes: PackedByteArray) -> Dictionary:
	if bytes.has(0):
		return _error("the file contains a NUL byte; a board file is plain text")
	return read(bytes.get_string_from_utf8())


## {"level": BoardLevel} or {"error": "what is wrong"} (the caller adds the file name).
## Callers holding bytes use read_bytes(), which also refuses NUL bytes.
static func read(text: String) -> Dictionary:
	if text.length() > BoardSchema.MAX_FILE_BYTES:
		return _error("the file is larger than %d bytes" % BoardSchema.MAX_FILE_BYTES)
	text = text.trim_prefix(char(0xFEFF))  # a UTF-8 byte order mark some editors add
	var gathered := _gather_lines(text)
	if gathered.has("error"):
		return gathered
	var data: Dictionary = gathered["data"]
	var problem := _check_header(data)
	if problem.is_empty():
		problem = _check_fields(data)
	if not problem.is_empty():
		return _error(problem)
	return {"level": BoardTextBuilder.build(data)}


# Folds the lines into one dictionary: fields by name, items appended to their list.
static func _gather_lines(text: String) -> Dictionary:
	var lines := text.split("\n")
	if lines.size() > BoardSchema.MAX_LINES:
		return _error("the file has %d lines; at most %d" % [lines.size(), BoardSchema.MAX_LINES])
	var data := {}
	var json := JSON.new()
	for number in lines.size():
		var line := lines[number].strip_edges()
		if line.is_empty():
			continue
		if json.parse(line) != OK:
			return _error(
				"line %d is not valid JSON: %s" % [number + 1, JsonErrors.parse_error(json)]
			)
		if not json.data is Dictionary:
			return _error("line %d is not a JSON object { ... }" % (number + 1))
		var repeated := JsonKeys.repeated(line, json.data)
		if not repeated.is_empty():
			return _error("line %d: %s" % [number + 1, JsonKeys.problem(repeated)])
		var object: Dictionary = json.data
		var problem := _gather(data, object)
		if not problem.is_empty():
			return _error("line %d: %s" % [number + 1, problem])
	return {"data": data}


static func _gather(data: Dictionary, line: Dictionary) -> String:
	var list := BoardSchema.list_of_key(line.keys()[0]) if line.size() == 1 else ""
	if not list.is_empty():
		var items: Array = data.get_or_add(list, [])
		items.append(line.values()[0])
		return ""
	for key: Variant in line.keys():
		if not BoardSchema.list_of_key(key).is_empty():
			return 'an item ("%s") must be alone on its line' % key
		if BoardSchema.is_list(key):
			return '"%s" items go one per line, not as a list' % key
		if key == "tuning" and data.has(key) and line.size() == 1:
			return _gather_tuning(data, line[key])
		if data.has(key):
			return 'the field "%s" is given twice' % key
		data[key] = line[key]
	return ""


# A tuning line after the first adds its constants to the ones read so far (files write one
# line per constant; older files hold them all on one line). A constant given twice is an error.
static func _gather_tuning(data: Dictionary, more: Variant) -> String:
	var tuning: Variant = data["tuning"]
	if not tuning is Dictionary or not more is Dictionary:
		return '"tuning" must be an object { ... }'
	var into: Dictionary = tuning
	var adding: Dictionary = more
	for key: Variant in adding:
		if into.has(key):
			return 'tuning "%s" is given twice' % key
		into[key] = adding[key]
	return ""


static func _check_header(data: Dictionary) -> String:
	if data.get("format") != BoardSchema.FORMAT:
		return '"format" must be "%s"; this is not a board file' % BoardSchema.FORMAT
	var version: Variant = data.get("format_version")
	if (
		(version is float or version is int)
		and BoardTextBuilder.float_of(version) > BoardSchema.FORMAT_VERSION
	):
		return (
			"the file is format version %s, newer than this game reads (%d): update the game"
			% [version, BoardSchema.FORMAT_VERSION]
		)
	var kind: Variant = data.get("kind")
	if BoardLevel.kind_named(kind) < 0:
		return '"kind" must be ' + BoardLevel.kind_choices()
	return ""


static func _check_fields(data: Dictionary) -> String:
	var kind: String = data["kind"]
	var fields := BoardSchema.fields_for(kind)
	var lists := BoardSchema.lists_for(kind)
	var optional := BoardSchema.optional_fields_for(kind)
	for key: Variant in data.keys():
		var known := fields.has(key) or lists.has(key) or optional.has(key)
		if not known and not key in OTHER_FIELDS:
			return 'unknown field "%s" for a %s board' % [key, kind]
	for field: String in optional:
		if data.has(field):
			var spec: Array = optional[field]
			var problem := BoardSchema.check_value(data[field], spec)
			if not problem.is_empty():
				return '"%s" %s' % [field, problem]
	for field: String in fields:
		if not data.has(field):
			return 'the field "%s" is missing' % field
		var spec: Array = fields[field]
		var problem := BoardSchema.check_value(data[field], spec)
		if not problem.is_empty():
			return '"%s" %s' % [field, problem]
	for list in lists:
		var problem := _check_list(list, data.get(list, []))
		if not problem.is_empty():
			return problem
	var pins: Array = data.get("pins", [])
	var pockets: Array = data.get("pockets", [])
	var pin_problem := _check_pin_pockets(pins, pockets)
	if not pin_problem.is_empty():
		return pin_problem
	var counters_problem := _check_counters(data.get(BoardSchema.NEXT_IDS_FIELD, {}), lists)
	if not counters_problem.is_empty():
		return counters_problem
	return _check_tuning(data.get("tuning", {}))


# The optional id counters: an object of the board's list names and whole numbers.
static func _check_counters(value: Variant, lists: Array[String]) -> String:
	var field: String = BoardSchema.NEXT_IDS_FIELD
	if not value is Dictionary:
		return '"%s" must be an object { ... }' % field
	var counters: Dictionary = value
	for key: Variant in counters.keys():
		if not key in lists:
			return '"%s" names "%s", which is not an item list of this board' % [field, key]
		var problem := BoardSchema.check_value(counters[key], BoardSchema.NEXT_ID_SPEC)
		if not problem.is_empty():
			return '"%s" "%s" %s' % [field, key, problem]
	return ""


static func _check_list(list: String, value: Variant) -> String:
	if not value is Array:
		return '"%s" must be a list [ ... ]' % list
	var items: Array = value
	var most := BoardSchema.most_items(list)
	if items.size() > most:
		return '"%s" has %d items; at most %d are allowed' % [list, items.size(), most]
	var required := BoardSchema.item_fields(list)
	var optional := BoardSchema.optional_item_fields(list)
	var checks := ItemKinds.of_list(list).checks
	for i in items.size():
		var problem := _check_item(items[i], required, optional)
		if problem.is_empty() and checks.is_valid():
			problem = checks.call(items[i])
		if not problem.is_empty():
			return "%s item %d: %s" % [list, i + 1, problem]
	return ""


# A pin of an older file names its pocket by number (0 = the first). The builder drops such
# pins, but one naming a pocket the board does not have is refused: the file is wrong.
static func _check_pin_pockets(pins: Array, pockets: Array) -> String:
	for i in pins.size():
		var pin: Dictionary = pins[i]
		var pocket := BoardTextBuilder.int_of(pin.get("pocket", -1))
		if pocket < pockets.size():
			continue
		var name := "pins item %d" % (i + 1)
		if pin.has("id"):
			name = "pin %d" % BoardTextBuilder.int_of(pin["id"])
		var has := "has no pockets"
		if not pockets.is_empty():
			has = "has %d pockets (0 to %d)" % [pockets.size(), pockets.size() - 1]
		return "%s names pocket %d; the board %s" % [name, pocket, has]
	return ""


static func _check_item(item: Variant, required: Dictionary, optional: Dictionary) -> String:
	if not item is Dictionary:
		return "must be an object { ... }"
	var fields: Dictionary = item
	for key: Variant in fields.keys():
		if not required.has(key) and not optional.has(key):
			return 'unknown field "%s"' % key
	for key: String in required:
		if not fields.has(key):
			return 'the field "%s" is missing' % key
		var spec: Array = required[key]
		var problem := BoardSchema.check_value(fields[key], spec)
		if not problem.is_empty():
			return '"%s" %s' % [key, problem]
	for key: String in optional:
		if fields.has(key):
			var spec: Array = optional[key]
			var problem := BoardSchema.check_value(fields[key], spec)
			if not problem.is_empty():
				return '"%s" %s' % [key, problem]
	return ""


static func _check_tuning(value: Variant) -> String:
	if not value is Dictionary:
		return '"tuning" must be an object { ... }'
	var known := BoardRanges.tuning_fields()
	var tuning: Dictionary = value
	for key: Variant in tuning.keys():
		var field: Variant = BoardSchema.RENAMED_TUNING.get(key, key)
		if not known.has(field):
			return 'unknown tuning field "%s"' % key
		if field != key and tuning.has(field):
			return 'tuning "%s" is the old name of "%s": give only one of them' % [key, field]
		var spec: Array = known[field]
		var type: int = spec[0]
		var type_name := (
			"vec2" if type == TYPE_VECTOR2 else ("int" if type == TYPE_INT else "float")
		)
		var problem := BoardSchema.check_value(tuning[key], [type_name, spec[1], spec[2]])
		if not problem.is_empty():
			return 'tuning "%s" %s' % [key, problem]
	return ""


static func _error(message: String) -> Dictionary:
	return {"error": message}
