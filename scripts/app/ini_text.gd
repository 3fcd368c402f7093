extends RefCounted
## A small INI reader and writer for the player's files (settings, best scores).
## `[section]` headers, `key=value` lines, `;` or `#` comments. Values are JSON
## (numbers, true/false, "strings", ["lists"]), which is also what Godot's ConfigFile
## writes for those types, so the files stay readable by both. Reading never prints engine
## errors: a damaged file comes back as one clear message the caller reports.


## Reads INI text. Returns {"sections": {name: {key: value}}} or {"error": "line N: ..."}.
static func parse(text: String) -> Dictionary:
	var sections := {}
	var current := ""
	var json := JSON.new()
	var line_number := 0
	for raw_line in text.split("\n"):
		line_number += 1
		var line := raw_line.strip_edges()
		if line.is_empty() or line.begins_with(";") or line.begins_with("#"):
			continue
		if line.begins_with("["):
			if not line.ends_with("]") or line.length() < 3:
				return {"error": "line %d: a section header must look like [name]" % line_number}
			current = line.substr(1, line.length() - 2).strip_edges()
			if not sections.has(current):
				sections[current] = {}
			continue
		var equals := line.find("=")
		if equals <= 0:
			return {"error": "line %d: expected key=value, found '%s'" % [line_number, line]}
		if current.is_empty():
			return {"error": "line %d: a value before any [section]" % line_number}
		var key := line.substr(0, equals).strip_edges()
		if json.parse(line.substr(equals + 1).strip_edges()) != OK:
			return {"error": "line %d: the value of '%s' is unreadable" % [line_number, key]}
		var section: Dictionary = sections[current]
		section[key] = json.data
	return {"sections": sections}


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
			lines.append("%s=%s" % [key, JSON.stringify(values[key])])
	return "\n".join(lines) + "\n"


## Reads a whole file: {"sections": ...}, {"missing": true} or {"error": "..."}.
static func read_file(path: String) -> Dictionary:
	if not FileAccess.file_exists(path):
		return {"missing": true}
	var file := FileAccess.open(path, FileAccess.READ)
	if file == null:
		return {"error": "cannot open it (%s)" % error_string(FileAccess.get_open_error())}
	var bytes := file.get_buffer(file.get_length())
	# checked on the raw bytes: decoding would quietly drop what makes the file unreadable
	if bytes.has(0):
		return {"error": "it is not a text file"}
	var text := bytes.get_string_from_utf8()
	if text.is_empty() and not bytes.is_empty():
		return {"error": "it is not UTF-8 text"}
	return parse(text)


## Writes text to a file through a temporary file, so a crash never leaves half a file.
static func write_file(path: String, text: String) -> Error:
	var temp_path := path + ".tmp"
	var file := FileAccess.open(temp_path, FileAccess.WRITE)
	if file == null:
		return FileAccess.get_open_error()
	file.store_string(text)
	file.close()
	return DirAccess.rename_absolute(temp_path, path)
