class_name JsonErrors
extends RefCounted
## Words a JSON parse error without quoting the file. Godot's parser says what it found
## ("Expected 'true', 'false', or 'null', got 'root'"), which would echo the first word of any
## file a refusal reads, a link to a system file included; a refusal names the problem only.


## The parse error of `json` (after a failed parse), with whatever it quoted from the text cut.
static func parse_error(json: JSON) -> String:
	var message := json.get_error_message()
	var quoted := message.find(", got ")
	if quoted < 0:
		return message
	var token := message.substr(quoted + 6).trim_suffix(".").trim_prefix("'").trim_suffix("'")
	if token.to_lower() in ["nan", "inf", "infinity", "-inf"]:
		return "NaN and infinity are not JSON numbers"
	if _is_engine_name(token):
		return "Godot values such as %s(...) are not JSON" % token
	return message.left(quoted)


## What a parsed JSON value is, for a message that must not quote it: "a number", "a text"...
static func kind_of(value: Variant) -> String:
	match typeof(value):
		TYPE_FLOAT, TYPE_INT:
			return "a number"
		TYPE_STRING:
			return "a text"
		TYPE_ARRAY:
			return "a list"
		TYPE_DICTIONARY:
			return "an object"
		TYPE_BOOL:
			return "true or false"
		TYPE_NIL:
			return "null"
	return "a value of another kind"


# True when `word` is a Godot class or built-in type name ("Object", "Vector2"): naming it
# says what kind of text was found without quoting anything else of the file.
static func _is_engine_name(word: String) -> bool:
	if ClassDB.class_exists(word):
		return true
	for type in TYPE_MAX:
		if type_string(type) == word:
			return true
	return false
