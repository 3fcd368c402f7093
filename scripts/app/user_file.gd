class_name UserFile
extends RefCounted
## The player's own files (settings, best results, the play-test request), handled as data:
## read as bytes and checked (size, encoding) before any parser sees them, so a damaged file
## becomes one clear sentence and never an engine error; a damaged file is moved aside to
## `<name>.bad-<YYYYMMDD-HHMMSS>` before a new one is written, so nothing the player had is lost.

## A settings or best-results file is a few kilobytes; anything past this is not one.
const MAX_BYTES := 1024 * 1024
## U+FEFF, the byte order mark a text may begin with.
const BYTE_ORDER_MARK := 0xFEFF


## Reads a text file: {"text": String} (a UTF-8 byte order mark dropped), {"missing": true},
## or {"error": why it cannot be text, for a sentence "… is damaged (<why>)"}.
static func read_text(path: String, max_bytes := MAX_BYTES) -> Dictionary:
	if not FileAccess.file_exists(path):
		return {"missing": true}
	var file := FileAccess.open(path, FileAccess.READ)
	if file == null:
		return {"error": "it cannot be opened: %s" % error_string(FileAccess.get_open_error())}
	var length := file.get_length()
	if length > max_bytes:
		return {
			"error":
			(
				"it is %s, larger than the %s such a file can be"
				% [size_text(length), size_text(max_bytes)]
			)
		}
	return decode(file.get_buffer(length))


## Bytes as text: {"text": String} or {"error": why}. Checked on the raw bytes, because
## decoding would quietly replace what makes the text unreadable (and print engine errors).
static func decode(bytes: PackedByteArray) -> Dictionary:
	if bytes.size() >= 2 and _is_utf16_mark(bytes[0], bytes[1]):
		return {"error": "it is UTF-16 text; save it as UTF-8"}
	if bytes.has(0):
		return {"error": "it is not a text file (it holds NUL bytes)"}
	var invalid := first_invalid_utf8(bytes)
	if invalid >= 0:
		return {"error": "it is not UTF-8 text (byte %d)" % invalid}
	var text := bytes.get_string_from_utf8()
	# A byte order mark some editors add is not part of the text. Compared by code point:
	# the release build's compressed scripts store string constants as UTF-8 and drop a
	# leading BOM when reading them back, so a "\ufeff" literal there is "" and every
	# text "begins with" it (which cut the first character off every file, issue 39).
	if not text.is_empty() and text.unicode_at(0) == BYTE_ORDER_MARK:
		text = text.substr(1)
	return {"text": text}


## The offset of the first byte that breaks UTF-8 (stray continuation, overlong form,
## surrogate, past U+10FFFF, cut-off sequence), or -1 when all of it is UTF-8.
static func first_invalid_utf8(bytes: PackedByteArray) -> int:
	var size := bytes.size()
	var at := 0
	while at < size:
		var lead := bytes[at]
		if lead < 0x80:
			at += 1
			continue
		# the continuation count, and the range the second byte must fall in for this lead
		var count := 0
		var low := 0x80
		var high := 0xBF
		if lead >= 0xC2 and lead <= 0xDF:
			count = 1
		elif lead >= 0xE0 and lead <= 0xEF:
			count = 2
			low = 0xA0 if lead == 0xE0 else 0x80
			high = 0x9F if lead == 0xED else 0xBF
		elif lead >= 0xF0 and lead <= 0xF4:
			count = 3
			low = 0x90 if lead == 0xF0 else 0x80
			high = 0x8F if lead == 0xF4 else 0xBF
		else:
			return at
		if at + count >= size or bytes[at + 1] < low or bytes[at + 1] > high:
			return at
		for next in range(at + 2, at + count + 1):
			if bytes[next] < 0x80 or bytes[next] > 0xBF:
				return at
		at += count + 1
	return -1


## Moves a damaged file aside to `<path>.bad-<YYYYMMDD-HHMMSS>` (with -2, -3… when that
## exists). Returns the new path, or "" when it could not be moved (then it is untouched).
static func keep_aside(path: String, when := Time.get_datetime_dict_from_system()) -> String:
	var stamp := (
		"%04d%02d%02d-%02d%02d%02d"
		% [when["year"], when["month"], when["day"], when["hour"], when["minute"], when["second"]]
	)
	var kept := "%s.bad-%s" % [path, stamp]
	var copy := 2
	while FileAccess.file_exists(kept):
		kept = "%s.bad-%s-%d" % [path, stamp, copy]
		copy += 1
	if DirAccess.rename_absolute(path, kept) != OK:
		return ""
	return kept


## The end of a message about a damaged file: where the old one went, or that it stays put.
static func kept_note(kept: String) -> String:
	if kept.is_empty():
		return "It could not be moved aside, so it is left as it is and nothing is saved to it."
	return "The old file is kept as %s." % kept


## The [meta] version of a parsed INI file: {"version": int} or {"error": why not}.
static func format_version(sections: Dictionary) -> Dictionary:
	var meta: Dictionary = sections.get("meta", {})
	if not meta.has("version"):
		return {"error": "it has no [meta] version line"}
	var version: Variant = meta["version"]
	var number: float = version if version is float or version is int else NAN
	if not is_finite(number) or number < 1.0 or number != floorf(number):
		return {"error": "its version is not a whole number from 1"}
	return {"version": int(minf(number, 1e9))}


## A byte count as a person reads it: "512 bytes", "4 KB", "1.5 MB".
static func size_text(bytes: int) -> String:
	if bytes >= 1024 * 1024:
		return "%s MB" % str(snappedf(bytes / (1024.0 * 1024.0), 0.1)).trim_suffix(".0")
	if bytes >= 1024:
		return "%s KB" % String.num(bytes / 1024.0, 0)
	return "%d bytes" % bytes


static func _is_utf16_mark(first: int, second: int) -> bool:
	return (first == 0xFF and second == 0xFE) or (first == 0xFE and second == 0xFF)
