extends RefCounted
## Replay text for the reader's tests: a header with every field good (change any of them),
## records after it, and what the reader makes of it.

const HASH := "0123456789abcdef0123456789abcdef0123456789abcdef0123456789abcdef"


## A good header of `game`, with `changes` over its fields.
static func header(game: String = "maze", changes: Dictionary = {}) -> Dictionary:
	var fields := {
		"replay": Replay.VERSION,
		"game": game,
		"board": "classic",
		"board_hash": HASH,
		"mode": "easy" if game == "maze" else "normal",
		"seed": 7,
		"step_hz": 240,
		"steps": 0,
		"state_hash": 5,
		"seconds": 0.0,
		"physics": 2,
		"rules": 1,
	}
	fields.merge(changes, true)
	return fields


## The reader's answer for the header line and then one line per record.
static func read(fields: Dictionary, records: Array = []) -> Dictionary:
	var lines := PackedStringArray([JSON.stringify(fields)])
	for record: Variant in records:
		lines.append(JSON.stringify(record))
	return ReplayReader.read("\n".join(lines))


## The reader's error for that text ("" when it reads).
static func error(fields: Dictionary, records: Array = []) -> String:
	return str(read(fields, records).get("error", ""))


## A good header of `game` whose records must add up to `steps`.
static func steps(count: int, game: String = "maze") -> Dictionary:
	return header(game, {"steps": count})
