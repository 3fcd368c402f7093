extends RefCounted
## Reads a board file as text before the engine parses it, so a broken or hostile file is
## refused with a clear message instead of engine parse errors, silently dropped values or
## code running: only the board scripts may be referenced, nothing may be embedded, every
## field must be one the board knows (or an old one the upgrader converts) with the right
## type. Returns the file's version (0 when it has no `version` line: the prototype format).

const BoardValueCheck := preload("res://tools/legacy_boards/board_value_check.gd")
const MAX_BYTES := 4 * 1024 * 1024


## {"error": "" or the problem, "version": int} for the file at `path`.
static func check(path: String) -> Dictionary:
	var file := FileAccess.open(path, FileAccess.READ)
	if file == null:
		return _fail("the file cannot be read (%s)" % error_string(FileAccess.get_open_error()))
	if file.get_length() > MAX_BYTES:
		@warning_ignore("integer_division")  # MAX_BYTES is a whole number of MB
		var megabytes := MAX_BYTES / 1024 / 1024
		return _fail("the file is larger than %d MB" % megabytes)
	var text := file.get_as_text()
	if text.strip_edges().is_empty():
		return _fail("the file is empty")
	var statements: Array[Dictionary] = []
	var split_error := _split(text, statements)
	if not split_error.is_empty():
		return _fail(split_error)
	return _check_statements(statements)


# Cuts the text into sections and `key = value` statements (values may span lines).
static func _split(text: String, out: Array[Dictionary]) -> String:
	var lines := text.split("\n")
	var i := 0
	while i < lines.size():
		var line := lines[i].strip_edges()
		var line_number := i + 1
		i += 1
		if line.is_empty() or line.begins_with(";"):
			continue
		if line.begins_with("["):
			if not line.ends_with("]"):
				return "line %d: a section header must end with ']'" % line_number
			out.append({"line": line_number, "section": line})
			continue
		var equals := line.find("=")
		var key := line.substr(0, equals).strip_edges() if equals > 0 else ""
		if out.is_empty():
			return "this is not a Godot text resource (it does not start with [gd_resource])"
		if not key.replace("/", "_").is_valid_identifier():
			return "line %d cannot be read: '%s'" % [line_number, line.left(40)]
		var value := line.substr(equals + 1).strip_edges()
		var state := _scan(value, [0, false])
		while (state[0] > 0 or state[1]) and i < lines.size():
			value += "\n" + lines[i]
			state = _scan(lines[i], state)
			i += 1
		if state[0] != 0 or state[1]:
			return "line %d: the value of '%s' is never closed" % [line_number, key]
		out.append({"line": line_number, "key": key, "value": value.strip_edges()})
	return ""


# Bracket depth and "inside a string" after `chunk`, continuing from `state`.
static func _scan(chunk: String, state: Array) -> Array:
	var depth: int = state[0]
	var quoted: bool = state[1]
	if not quoted and not chunk.contains('"'):
		depth += chunk.count("(") + chunk.count("[") + chunk.count("{")
		depth -= chunk.count(")") + chunk.count("]") + chunk.count("}")
		return [depth, false]
	var escaped := false
	for c in chunk:
		if quoted:
			if escaped:
				escaped = false
			elif c == "\\":
				escaped = true
			elif c == '"':
				quoted = false
		elif c == '"':
			quoted = true
		elif c == "(" or c == "[" or c == "{":
			depth += 1
		elif c == ")" or c == "]" or c == "}":
			depth -= 1
	return [depth, quoted]


static func _check_statements(statements: Array[Dictionary]) -> Dictionary:
	if statements.is_empty() or not statements[0].has("section"):
		return _fail("this is not a Godot text resource")
	var problem := _check_header(_attributes(str(statements[0]["section"])))
	var ext_scripts := {}  # id → class name
	var sections: Array[Dictionary] = []  # {tag, id, line, fields: {key: [line, value]}}
	if problem.is_empty():
		problem = _collect_sections(statements, ext_scripts, sections)
	if problem.is_empty():
		problem = _assign_classes(sections, ext_scripts)
	if problem.is_empty():
		problem = _check_fields_in_order(sections, ext_scripts)
	if not problem.is_empty():
		return _fail(problem)
	var main_fields: Dictionary = sections[-1]["fields"]
	return _read_version(main_fields)


# The [gd_resource] line: a text resource in a format this build reads, holding a BoardLevel.
static func _check_header(header: Dictionary) -> String:
	if header.get("tag", "") != "gd_resource":
		return "this is not a Godot text resource (it starts with %s)" % header.get("tag", "?")
	if not header.get("format", "3") in ["3", "4"]:
		return "the file uses resource format %s, which this build cannot read" % header["format"]
	if (
		header.get("type", "") != "Resource"
		or header.get("script_class", "BoardLevel") != "BoardLevel"
	):
		return (
			"the file holds a %s, not a BoardLevel"
			% header.get("script_class", header.get("type", "?"))
		)
	return ""


# Sorts the statements after the header into board scripts (`ext_scripts`, id → class name)
# and sections with their fields; the last section must be the [resource].
static func _collect_sections(
	statements: Array[Dictionary], ext_scripts: Dictionary, sections: Array[Dictionary]
) -> String:
	for statement: Dictionary in statements.slice(1):
		if statement.has("section"):
			var problem := _open_section(statement, ext_scripts, sections)
			if not problem.is_empty():
				return problem
		elif sections.is_empty():
			return "line %d has a field outside any section" % statement["line"]
		else:
			var fields: Dictionary = sections[-1]["fields"]
			fields[statement["key"]] = [statement["line"], statement["value"]]
	if sections.is_empty() or sections[-1]["tag"] != "resource":
		return "the file has no [resource] section"
	return ""


# One section header: a board script reference, or a section whose fields follow.
static func _open_section(
	statement: Dictionary, ext_scripts: Dictionary, sections: Array[Dictionary]
) -> String:
	var attributes := _attributes(str(statement["section"]))
	var tag: String = attributes.get("tag", "")
	if tag == "ext_resource":
		var script_path: String = attributes.get("path", "")
		if (
			attributes.get("type", "") != "Script"
			or not BoardValueCheck.ALLOWED_SCRIPTS.has(script_path)
		):
			return (
				"line %d refers to %s, but a board may only use the board scripts"
				% [statement["line"], script_path]
			)
		ext_scripts[attributes.get("id", "")] = BoardValueCheck.ALLOWED_SCRIPTS[script_path]
	elif tag == "sub_resource" or tag == "resource":
		if tag == "sub_resource" and attributes.get("type", "") != "Resource":
			return (
				"line %d embeds a %s, which a board never contains"
				% [statement["line"], attributes.get("type", "?")]
			)
		sections.append(
			{"tag": tag, "id": attributes.get("id", ""), "line": statement["line"], "fields": {}}
		)
	else:
		return "line %d has an unknown section [%s]" % [statement["line"], tag]
	return ""


# Each section's class comes from its `script` line; the [resource] must be a BoardLevel.
static func _assign_classes(sections: Array[Dictionary], ext_scripts: Dictionary) -> String:
	for section in sections:
		var fields: Dictionary = section["fields"]
		var script_ref: String = fields.get("script", [0, ""])[1]
		var class_id := BoardValueCheck.ref_id(script_ref, "Ext")
		if not ext_scripts.has(class_id):
			return "line %d: a section has no board script" % section["line"]
		section["class"] = ext_scripts[class_id]
	if sections[-1]["class"] != "BoardLevel":
		return "the file holds a %s, not a BoardLevel" % sections[-1]["class"]
	return ""


# A section may only use sub-resources defined above it, as the engine reads them.
static func _check_fields_in_order(sections: Array[Dictionary], ext_scripts: Dictionary) -> String:
	var sub_classes := {}  # id → class name
	for section in sections:
		var problem := BoardValueCheck.check_fields(section, ext_scripts, sub_classes)
		if not problem.is_empty():
			return problem
		if section["tag"] == "sub_resource":
			sub_classes[section["id"]] = section["class"]
	return ""


static func _read_version(main_fields: Dictionary) -> Dictionary:
	var version := 0
	if main_fields.has("version"):
		var version_line: Array = main_fields["version"]
		version = str(version_line[1]).to_int()
	if version < 0 or version > BoardLevel.CURRENT_VERSION:
		return _fail(
			"unknown version %d (this build reads 0 to %d)" % [version, BoardLevel.CURRENT_VERSION]
		)
	return {"error": "", "version": version}


static func _attributes(header: String) -> Dictionary:
	var inner := header.substr(1, header.length() - 2).strip_edges()
	var tag := inner.get_slice(" ", 0)
	var result := {"tag": tag}
	var pattern := RegEx.create_from_string('(\\w+)=("([^"]*)"|[^\\s\\]"]+)')
	var rest := inner.substr(tag.length())
	for found in pattern.search_all(rest):
		var quoted := found.get_string(3)
		result[found.get_string(1)] = quoted if found.get_start(3) >= 0 else found.get_string(2)
	# Anything besides the tag and key=value pairs: the engine would not read it either.
	if not tag.is_valid_identifier() or not pattern.sub(rest, "", true).strip_edges().is_empty():
		result["tag"] = "(unreadable)"
	return result


static func _fail(problem: String) -> Dictionary:
	return {"error": problem, "version": -1}
