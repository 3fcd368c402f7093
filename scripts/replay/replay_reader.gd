class_name ReplayReader
extends RefCounted
## Reads a replay file's text into a Replay, as data only: every line goes to Godot's JSON
## parser (plain values; NaN and deep nesting refused), then every field and record is checked
## (type, whole numbers, ranges, sizes, record kinds for the game, event step counts, the
## step total) before a Replay is built in code. A replay cannot name a script, a class, or a
## file: the board is found by id and checked by its content hash.

## Largest file read, in characters (about ten minutes of the busiest maze input).
const MAX_BYTES := 2 * 1024 * 1024
## Most lines (records) in one file.
const MAX_LINES := 100_000
## Most fixed steps in one replay: ten minutes at 240 steps a second, longer than any maze
## attempt or pachinko game takes (the recorder stops there too). Playing the longest back
## costs seconds of CPU, not the minute an hour-long file took.
const MAX_STEPS := 144_000
## Steps one frame can run: the world runs at most this many per frame.
const MAX_STEPS_PER_FRAME := BallWorld.MAX_STEPS_PER_ADVANCE
## Largest tilt in hundredths of a degree (MazeRules keeps it within ±12°).
const MAX_TILT := 1200
## Largest shot power in hundredths (power 0..100).
const MAX_POWER := 10000
## Largest seed and state hash kept exactly: JSON numbers are doubles.
const MAX_WHOLE := 9_007_199_254_740_991
const HEADER_KEYS := [
	"replay",
	"game",
	"board",
	"board_hash",
	"mode",
	"seed",
	"step_hz",
	"steps",
	"state_hash",
	"seconds",
	"physics",
	"rules",
]
## Header fields older formats do not have: field -> first format with it.
const LATER_KEYS := {"physics": 3, "rules": 4}
## Physics versions a file may name (BallWorld keeps its history small).
const MAX_PHYSICS := 1000
const MODES := {Replay.MAZE: ["easy", "hard"], Replay.PACHINKO: [Replay.PACHINKO_MODE]}
## Longest packed text of one "tilts" record: MAX_PACKED_FRAMES frames of three numbers of
## at most TiltPacking.MAX_DIGITS digits.
const MAX_PACKED_CHARS := Replay.MAX_PACKED_FRAMES * 3 * TiltPacking.MAX_DIGITS


## {"replay": Replay} or {"error": "what is wrong"} (the caller adds the file name).
## NUL bytes are refused by the caller (ReplayStore) on the raw bytes: a Godot String cannot
## hold one, decoding turns it into U+FFFD.
static func read(text: String) -> Dictionary:
	if text.length() > MAX_BYTES:
		return _error("the file is larger than %d bytes" % MAX_BYTES)
	text = text.trim_prefix(char(0xFEFF))
	var lines := text.split("\n")
	if lines.size() > MAX_LINES:
		return _error("the file has %d lines; at most %d" % [lines.size(), MAX_LINES])
	var replay := Replay.new()
	var json := JSON.new()
	var header_seen := false
	var step := 0
	for number in lines.size():
		var line := lines[number].strip_edges()
		if line.is_empty():
			continue
		if json.parse(line) != OK:
			return _error(
				"line %d is not valid JSON: %s" % [number + 1, JsonErrors.parse_error(json)]
			)
		var repeated := JsonKeys.repeated(line, json.data)
		if not repeated.is_empty():
			return _error("line %d: %s" % [number + 1, JsonKeys.problem(repeated)])
		var problem := ""
		if not header_seen:
			header_seen = true
			problem = _read_header(json.data, replay)
		else:
			var counted := _read_record(json.data, replay, step)
			problem = counted.get("error", "")
			step = counted.get("step", step)
		if not problem.is_empty():
			return _error("line %d: %s" % [number + 1, problem])
	if not header_seen:
		return _error("the file is empty")
	if step != replay.steps:
		return _error("the records run %d steps but the header says %d" % [step, replay.steps])
	return {"replay": replay}


static func _read_header(data: Variant, replay: Replay) -> String:
	if not data is Dictionary:
		return "the first line must be the header object { ... }"
	var header: Dictionary = data
	for key: Variant in header:
		if not HEADER_KEYS.has(key):
			return 'unknown header field "%s"' % str(key)
	if not header.has("replay"):
		return 'the header has no "replay"'
	var version: Variant = _whole(header["replay"], 1, MAX_WHOLE)
	if version == null:
		return '"replay" (the format version) must be a whole number from 1'
	if version > Replay.VERSION:
		return (
			"format %d is newer than this game reads (%d): update the game"
			% [version, Replay.VERSION]
		)
	replay.format_version = version
	for key: String in HEADER_KEYS:
		var since: int = LATER_KEYS.get(key, 1)
		if version >= since and not header.has(key):
			return 'the header has no "%s"' % key
		if version < since and header.has(key):
			return '"%s" came with format %d; this file says format %d' % [key, since, version]
	if not header.has("physics"):
		header["physics"] = 1  # files before format 3 were recorded with physics 1
	if not header.has("rules"):
		header["rules"] = 1  # files before format 4 were recorded with rules 1
	var problem := _read_names(header, replay)
	if not problem.is_empty():
		return problem
	return _read_numbers(header, replay)


static func _read_names(header: Dictionary, replay: Replay) -> String:
	var game: Variant = header["game"]
	if not MODES.has(game):
		return '"game" must be ' + BoardLevel.kind_choices()
	replay.game = game
	var board := str(header["board"]) if header["board"] is String else ""
	if board.is_empty() or board.length() > 64:
		return '"board" must be a board id of 1 to 64 characters'
	for character in board:
		if character.unicode_at(0) < 32:
			return '"board" contains a control character'
	replay.board_id = board
	var board_hash := str(header["board_hash"]) if header["board_hash"] is String else ""
	if board_hash.length() != 64 or not board_hash.is_valid_hex_number():
		return '"board_hash" must be 64 hexadecimal digits (a SHA-256)'
	replay.board_hash = board_hash.to_lower()
	var modes: Array = MODES[game]
	if not modes.has(header["mode"]):
		return '"mode" of a %s replay must be one of %s' % [game, ", ".join(modes)]
	replay.hard = header["mode"] == "hard"
	return ""


static func _read_numbers(header: Dictionary, replay: Replay) -> String:
	var checks := [
		["seed", -MAX_WHOLE, MAX_WHOLE],
		["step_hz", 1, 1000],
		["steps", 0, MAX_STEPS],
		["state_hash", 0, MAX_WHOLE],
		["physics", 1, MAX_PHYSICS],
		["rules", 1, MAX_PHYSICS],
	]
	for check: Array in checks:
		var low: int = check[1]
		var high: int = check[2]
		var whole: Variant = _whole(header[check[0]], low, high)
		if whole == null:
			return '"%s" must be a whole number from %d to %d' % check
		header[check[0]] = whole
	replay.rng_seed = header["seed"]
	replay.step_hz = header["step_hz"]
	replay.steps = header["steps"]
	replay.state_hash = header["state_hash"]
	replay.physics_version = header["physics"]
	replay.rules_version = header["rules"]
	var value: Variant = header["seconds"]
	var seconds: float = value if value is float or value is int else -1.0
	if not is_finite(seconds) or seconds < 0.0:
		return '"seconds" must be a finite number >= 0'
	replay.seconds = seconds
	return ""


# One record: {"step": steps counted after it} or {"error": ...}.
static func _read_record(data: Variant, replay: Replay, step: int) -> Dictionary:
	var record: Array = data if data is Array else []
	if record.is_empty() or not record[0] is String:
		return {"error": 'a record must be an array that starts with its name, like ["tilt", ...]'}
	var sizes: Dictionary = Replay.RECORD_SIZES[replay.game]
	var kind: String = record[0]
	if not sizes.has(kind):
		var known := ", ".join(PackedStringArray(sizes.keys()))
		return {"error": 'unknown %s record "%s" (known: %s)' % [replay.game, kind, known]}
	if kind == "tilts":
		return _read_packed(record, replay, step)
	var size: int = sizes[kind]
	if record.size() != size + 1:
		return {"error": '"%s" takes %d numbers, got %d' % [kind, size, record.size() - 1]}
	var numbers: Array[int] = []
	for i in range(1, record.size()):
		var value: Variant = _whole(record[i], -MAX_WHOLE, MAX_WHOLE)
		if value == null:
			return {"error": '"%s": item %d must be a whole number' % [kind, i]}
		numbers.append(value)
	var problem := _check_record(kind, numbers, step)
	if not problem.is_empty():
		return {"error": problem}
	var built: Array = [kind]
	built.append_array(numbers)
	replay.records.append(built)
	if kind == "tilt" or kind == "run":
		step += numbers[0] * numbers[1]
		if step > MAX_STEPS:
			return {"error": "more than %d steps in all" % MAX_STEPS}
	return {"step": step}


# A "tilts" record: ["tilts", "packed frames"], unpacked and checked frame by frame.
static func _read_packed(record: Array, replay: Replay, step: int) -> Dictionary:
	if replay.format_version < 2:
		return {"error": '"tilts" records came with format 2; this file says format 1'}
	if record.size() != 2 or not record[1] is String:
		return {"error": '"tilts" takes one text of packed frames, like ["tilts", "CAA"]'}
	var packed: String = record[1]
	if packed.length() > MAX_PACKED_CHARS:
		return {
			"error": '"tilts": the packed frames are longer than %d characters' % MAX_PACKED_CHARS
		}
	var unpacked := TiltPacking.decode(packed)
	if unpacked.has("error"):
		return {"error": '"tilts": %s' % unpacked["error"]}
	var numbers: Array = unpacked["numbers"]
	if numbers.size() > Replay.MAX_PACKED_FRAMES * 3:
		return {"error": '"tilts": more than %d frames' % Replay.MAX_PACKED_FRAMES}
	for index in range(0, numbers.size(), 3):
		var frame: Array[int] = [1, numbers[index], numbers[index + 1], numbers[index + 2]]
		var problem := _check_record("tilt", frame, step)
		if not problem.is_empty():
			return {"error": problem.replace('"tilt"', '"tilts"')}
		step += numbers[index]
	if step > MAX_STEPS:
		return {"error": "more than %d steps in all" % MAX_STEPS}
	var built: Array = ["tilts"]
	built.append_array(numbers)
	replay.records.append(built)
	return {"step": step}


static func _check_record(kind: String, numbers: Array[int], step: int) -> String:
	if kind == "tilt" or kind == "run":
		if numbers[0] < 1 or numbers[0] > MAX_STEPS:
			return '"%s": the frame count must be 1 to %d' % [kind, MAX_STEPS]
		if numbers[1] < 1 or numbers[1] > MAX_STEPS_PER_FRAME:
			return '"%s": steps per frame must be 1 to %d' % [kind, MAX_STEPS_PER_FRAME]
	if kind == "tilt":
		for tilt: int in [numbers[2], numbers[3]]:
			if absi(tilt) > MAX_TILT:
				return '"tilt": a tilt must be within ±%d hundredths of a degree' % MAX_TILT
	if kind == "start" or kind == "fire" or kind == "house":
		if numbers[0] != step:
			return '"%s" says step %d but the records before it run %d' % [kind, numbers[0], step]
	if kind == "fire" and (numbers[1] < 0 or numbers[1] > MAX_POWER):
		return '"fire": power must be 0 to %d hundredths' % MAX_POWER
	return ""


# The value as an int when it is a whole number within [low, high], else null.
static func _whole(value: Variant, low: int, high: int) -> Variant:
	if not (value is float or value is int):
		return null
	var number: float = value
	if not is_finite(number) or number != floorf(number):
		return null
	if number < float(low) or number > float(high):
		return null
	return int(number)


static func _error(message: String) -> Dictionary:
	return {"error": message}
