extends RefCounted
## The layer list of docs/architecture.md: under its "## Layers" heading, numbered lines
## naming folders in backticks (`scripts/physics/`, `scripts/*/autoplay/`; `*` is any one
## folder), lowest layer first. A file is in the layer of the most specific folder matching it.

## Why the list could not be read ("" when it was).
var problem := ""
# Per folder pattern: its folder names, and the number of its layer (1 = lowest).
var _patterns: Array[PackedStringArray] = []
var _pattern_layer := PackedInt32Array()
# Per layer number - 1: its folders as written, for messages.
var _layer_folders := PackedStringArray()


## Reads the list from the text of docs/architecture.md.
func _init(markdown: String) -> void:
	var in_section := false
	var folder_pattern := RegEx.create_from_string("`([^`]+/)`")
	for line in markdown.split("\n"):
		if line.begins_with("## "):
			in_section = line.strip_edges() == "## Layers"
			continue
		if not in_section or not _is_numbered(line):
			continue
		var number := int(line.get_slice(".", 0))
		if number != _layer_folders.size() + 1:
			problem = "layer %d is numbered %d in the list" % [_layer_folders.size() + 1, number]
			return
		var folders := PackedStringArray()
		for found: RegExMatch in folder_pattern.search_all(line.get_slice(":", 0)):
			folders.append(found.get_string(1))
			_patterns.append(found.get_string(1).trim_suffix("/").split("/"))
			_pattern_layer.append(number)
		if folders.is_empty():
			problem = "layer %d names no folder in backticks" % number
			return
		_layer_folders.append(", ".join(folders))
	if _layer_folders.is_empty():
		problem = 'no numbered list under a "## Layers" heading'


## How many layers the list has.
func size() -> int:
	return _layer_folders.size()


## The layer number (1 = lowest) of the file at `path` (relative to res://), 0 for none.
func layer_of(path: String) -> int:
	var parts := path.split("/")
	var best := 0
	var best_depth := 0
	for p in _patterns.size():
		var folders := _patterns[p]
		if folders.size() <= best_depth or folders.size() >= parts.size():
			continue
		var matches := true
		for k in folders.size():
			if not parts[k].match(folders[k]):
				matches = false
				break
		if matches:
			best = _pattern_layer[p]
			best_depth = folders.size()
	return best


## Layer `number` for a message: "layer 2 (scripts/board/)".
func describe(number: int) -> String:
	return "layer %d (%s)" % [number, _layer_folders[number - 1]]


static func _is_numbered(line: String) -> bool:
	var dot := line.find(". ")
	return dot > 0 and line.left(dot).is_valid_int()
