extends RefCounted
## What one GDScript file uses, read from its text: the `res://….gd` paths in its code
## (preload, load, extends "…") and the global names (class_name, autoload) it names in code.
## Comments, doc comments and other strings are skipped, so a name in prose is not a use.

# One token at a time, leftmost first: a triple-quoted string, a one-line string, a comment,
# or a name. A name right after ".", "$" or "%" is a member or a node, and one glued to a
# word character is part of a number ("0x1F"), so neither is read as a name.
const _TOKEN := (
	"\"\"\"[\\s\\S]*?\"\"\"|'''[\\s\\S]*?'''"
	+ "|\"(?:[^\"\\\\\\n]|\\\\.)*\"|'(?:[^'\\\\\\n]|\\\\.)*'"
	+ "|#[^\\n]*"
	+ "|(?<![\\w.$%])[A-Za-z_]\\w*"
)
const _CLASS_NAME := "(?m)^class_name\\s+([A-Za-z_]\\w*)"

static var _token: RegEx
static var _class_name: RegEx


## The global class name `text` declares, or "" when it declares none.
static func declared_class(text: String) -> String:
	if _class_name == null:
		_class_name = RegEx.create_from_string(_CLASS_NAME)
	var found := _class_name.search(text)
	return found.get_string(1) if found != null else ""


## Every file `text` uses, as {target path: first line using it}. `names` maps each global
## name (class_name or autoload) to its file; a `res://` path counts when it ends in ".gd".
## Paths come back without "res://"; a file's use of itself is left out (`own_path`).
static func uses(text: String, own_path: String, names: Dictionary) -> Dictionary:
	if _token == null:
		_token = RegEx.create_from_string(_TOKEN)
	var found := {}
	for token: RegExMatch in _token.search_all(text):
		var word := token.get_string()
		var target := ""
		var first := word.unicode_at(0)
		if first == 34 or first == 39:  # a string: " or '
			var inner := word.substr(1, word.length() - 2)
			if inner.begins_with("res://") and inner.ends_with(".gd"):
				target = inner.trim_prefix("res://")
		elif first != 35 and names.has(word):  # not a comment (#): a name
			target = names[word]
		if target.is_empty() or target == own_path or found.has(target):
			continue
		var start := token.get_start()
		# count()'s end 0 means "to the end", so a token at the very start is line 1 here.
		found[target] = 1 if start == 0 else text.count("\n", 0, start) + 1
	return found
