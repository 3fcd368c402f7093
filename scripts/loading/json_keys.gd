class_name JsonKeys
extends RefCounted
## Finds a key given twice in one JSON object. Godot's JSON parser keeps the last value of a
## repeated key without a word, so a file could say one thing to a person reading it and
## another to the game; every reader of JSON from a file checks its text here and refuses it.

## A repeated key is quoted at most this long in a message.
const QUOTED_CHARS := 40

## What `repeated` returns for a repeated empty key (`{"": 1, "": 2}`), since its own
## answer for "no repeat" is "".
const EMPTY_KEY := '""'


## The first key that appears twice in the same object of `text` (EMPTY_KEY for the empty
## key), or "" when none does. `text` must already have parsed as JSON (the scan trusts its
## strings to be closed); `parsed`, what it parsed to, lets most lines skip the scan.
static func repeated(text: String, parsed: Variant = null) -> String:
	if not text.contains(","):
		return ""  # two keys in one object need a comma between them
	if parsed != null and text.count(":") == _key_count(parsed):
		return ""  # every key is followed by a colon, so no key was dropped by the parser
	var objects: Array = []  # one entry per open bracket: {key: true} for {, null for [
	var at := 0
	var length := text.length()
	while at < length:
		var character := text[at]
		if character == '"':
			var end := _string_end(text, at)
			if _followed_by_colon(text, end + 1) and not objects.is_empty():
				var open: Variant = objects.back()
				if open is Dictionary:
					var keys: Dictionary = open
					var key := _decoded(text.substr(at, end - at + 1))
					if keys.has(key):
						return key if not key.is_empty() else EMPTY_KEY
					keys[key] = true
			at = end + 1
			continue
		if character == "{":
			objects.append({})
		elif character == "[":
			objects.append(null)
		elif character == "}" or character == "]":
			objects.pop_back()
		at += 1
	return ""


# How many keys the parsed `value` holds, at every depth.
static func _key_count(value: Variant) -> int:
	var count := 0
	if value is Dictionary:
		var object: Dictionary = value
		count = object.size()
		for inner: Variant in object.values():
			count += _key_count(inner)
	elif value is Array:
		for inner: Variant in value:
			count += _key_count(inner)
	return count


## The problem for a repeated `key`, as the readers word it.
static func problem(key: String) -> String:
	if key == EMPTY_KEY:
		return 'the empty key "" is given twice'
	var shown := key if key.length() <= QUOTED_CHARS else key.left(QUOTED_CHARS) + "…"
	return 'the key "%s" is given twice' % shown.c_escape()


# The index of the quote closing the string that opens at `start`.
static func _string_end(text: String, start: int) -> int:
	var at := text.find('"', start + 1)
	while at > 0:
		var backslashes := 0
		while text[at - 1 - backslashes] == "\\":
			backslashes += 1
		if backslashes % 2 == 0:
			return at
		at = text.find('"', at + 1)
	return text.length() - 1


static func _followed_by_colon(text: String, from: int) -> bool:
	var at := from
	while at < text.length() and text[at] in [" ", "\t", "\r", "\n"]:
		at += 1
	return at < text.length() and text[at] == ":"


# A quoted key as its text: "a" and "\u0061" are the same key to the parser.
static func _decoded(quoted: String) -> String:
	if not quoted.contains("\\"):
		return quoted.substr(1, quoted.length() - 2)
	var value: Variant = JSON.parse_string(quoted)
	return value if value is String else quoted
