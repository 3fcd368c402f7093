class_name IniText
extends RefCounted
## A small INI reader and writer for the player's files (settings, best results), data only.
## `[section]` headers, `key=value` lines, `;` or `#` comments. Values are JSON (numbers,
## true/false, "strings", ["lists"]), read by the JSON parser, which only makes plain values.
## A key is written bare when it is a plain name and as a JSON string otherwise, so any key
## (a board id with `=`, `]`, `;`, quotes, a newline, any Unicode) reads back the same.
## Reading never prints engine errors: a line it cannot read is skipped and named in
## "problems"; the caller decides what that means for the file.

## Line problems listed by name; past this only their count is given.
const MAX_LISTED_PROBLEMS := 5
const PLAIN_KEY := "^[A-Za-z0-9_][A-Za-z0-9_.\\-]*$"


## Reads INI text: {"sections": {name: {key: value}}, "problems": PackedStringArray (the
## first few unreadable lines, short enough for a player's message: "volume (line 4)",
## "line 7 (no =)"), "problem_count": int}.
static func parse(text: String) -> Dictionary:
	var sections := {}
	var problems := PackedStringArray()
	var problem_count := 0
	var current := ""  # the section lines go into
	var in_section := false  # false before the first header and after a broken one
	var json := JSON.new()
	var line_number := 0
	for raw_line in text.split("\n"):
		line_number += 1
		var line := raw_line.strip_edges()  # also drops the \r of a CRLF file
		if line.is_empty() or line.begins_with(";") or line.begins_with("#"):
			continue
		var problem := ""
		if line.begins_with("["):
			in_section = line.ends_with("]") and line.length() >= 3
			if in_section:
				current = line.substr(1, line.length() - 2).strip_edges()
				if not sections.has(current):
					sections[current] = {}
			else:
				problem = "line %d (not a [section])"
		elif not in_section:
			problem = "line %d (outside a [section])"
		else:
			var section: Dictionary = sections[current]
			problem = _read_pair(line, json, section)
		if not problem.is_empty():
			problem_count += 1
			if problems.size() < MAX_LISTED_PROBLEMS:
				problems.append(problem % line_number)
	return {"sections": sections, "problems": problems, "problem_count": problem_count}


## Writes sections (an Array of [name, Dictionary] pairs, in order) after a comment header.
static func format(header: String, sections: Array) -> String:
	var lines := PackedStringArray()
	for comment in header.split("\n"):
		lines.append("; " + comment)
	for pair: Array in sections:
		lines.append("")
		lines.append("[%s]" % pair[0])
		var values: Dictionary = pair[1]
		for key: String in values:
			lines.append("%s=%s" % [key_text(key), _json_line(values[key])])
	return "\n".join(lines) + "\n"


## A key as written: bare when it is a plain name, else a JSON string.
static func key_text(key: String) -> String:
	if RegEx.create_from_string(PLAIN_KEY).search(key) != null:
		return key
	return _json_line(key)


## Reads a whole file: {"sections", "problems", "problem_count"} as `parse` gives,
## {"missing": true} or {"error": "..."} when it is no text at all (see UserFile.read_text).
static func read_file(path: String) -> Dictionary:
	var read := UserFile.read_text(path)
	if not read.has("text"):
		return read
	var text: String = read["text"]
	return parse(text)


## Reads a player's file that has a [meta] version: {"missing": true}; {"error": why} when
## it is no usable file (not text, or no whole-number version); else {"sections",
## "version": int, "problems": the unreadable lines, a few named and then a count}.
static func read_versioned_file(path: String) -> Dictionary:
	var read := read_file(path)
	if not read.has("sections"):
		return read
	var sections: Dictionary = read["sections"]
	var problems: PackedStringArray = read["problems"]
	var version := UserFile.format_version(sections)
	if version.has("error"):
		var why: String = version["error"]
		if not problems.is_empty():
			why += "; unreadable: " + problems[0]
		return {"error": why}
	var unlisted: int = read["problem_count"] - problems.size()
	if unlisted > 0:
		problems.append("%d more lines" % unlisted)
	return {"sections": sections, "version": version["version"], "problems": problems}


## Writes text to a file through a fresh temporary file (SafeWrite), so a crash never leaves
## half a file and a planted link is never written through.
static func write_file(path: String, text: String) -> Error:
	return SafeWrite.write_text(path, text)


# Reads one `key=value` line into `section`; "" or the problem, with a %d for the line.
static func _read_pair(line: String, json: JSON, section: Dictionary) -> String:
	var key := ""
	var rest := ""
	if line.begins_with('"'):
		var end := _closing_quote(line)
		if end < 0 or json.parse(line.substr(0, end + 1)) != OK or not json.data is String:
			return "line %d (a quoted key must be one JSON string)"
		key = json.data
		rest = line.substr(end + 1).strip_edges()
		if not rest.begins_with("="):
			return "line %d (no = after the key)"
		rest = rest.substr(1)
	else:
		var equals := line.find("=")
		if equals <= 0:
			return "line %d (no =)"
		key = line.substr(0, equals).strip_edges()
		rest = line.substr(equals + 1)
	if json.parse(rest.strip_edges()) != OK or not JsonKeys.repeated(rest).is_empty():
		return "%s (line %%d)" % key.left(40).c_escape().replace("%", "%%")
	section[key] = json.data  # a repeated key: the last one counts, as the file reads
	return ""


# The index of the quote closing the JSON string that opens `line`, or -1.
static func _closing_quote(line: String) -> int:
	var at := 1
	while at < line.length():
		var code := line.unicode_at(at)
		if code == 0x5C:  # a backslash: the next character is escaped
			at += 2
			continue
		if code == 0x22:
			return at
		at += 1
	return -1


# JSON for one line: control characters the JSON writer leaves raw are escaped too.
static func _json_line(value: Variant) -> String:
	var text := JSON.stringify(value)
	var clean := true
	for at in text.length():
		var code := text.unicode_at(at)
		if code < 0x20 or code == 0x7F:
			clean = false
			break
	if clean:
		return text
	var escaped := PackedStringArray()
	for at in text.length():
		var code := text.unicode_at(at)
		escaped.append("\\u%04x" % code if code < 0x20 or code == 0x7F else text[at])
	return "".join(escaped)
