extends RefCounted
## The field-by-field half of board_file_check.gd: every field of a section must be one its
## script declares (or an old one board_upgrader.gd converts) and its text must have the right
## shape before str_to_var (which could build any object) ever sees it.

const BoardUpgrader := preload("res://tools/legacy_boards/board_upgrader.gd")

## The only scripts a board file may use, and the class each one defines.
const ALLOWED_SCRIPTS := {
	"res://scripts/board/board_level.gd": "BoardLevel",
	"res://scripts/board/pocket_spec.gd": "PocketSpec",
	"res://scripts/physics/physics_tuning.gd": "PhysicsTuning",
}
## Fields every Resource may carry in a file.
const BUILTIN_FIELDS := ["script", "resource_name", "resource_local_to_scene", "resource_path"]
## Variant type → constructor name written in text resources.
const CONSTRUCTORS := {
	TYPE_VECTOR2: "Vector2",
	TYPE_VECTOR2I: "Vector2i",
	TYPE_RECT2: "Rect2",
	TYPE_COLOR: "Color",
	TYPE_PACKED_VECTOR2_ARRAY: "PackedVector2Array",
	TYPE_PACKED_INT32_ARRAY: "PackedInt32Array",
	TYPE_PACKED_BYTE_ARRAY: "PackedByteArray",
	TYPE_PACKED_FLOAT32_ARRAY: "PackedFloat32Array",
}
const REF_PATTERN := '^(Ext|Sub)Resource\\("([^"]+)"\\)$'
const TYPED_ARRAY_PATTERN := '^Array\\[ExtResource\\("([^"]+)"\\)\\]\\((.*)\\)$'
const NUMBER_PATTERN := "^[-+]?(\\d+\\.?\\d*|\\.\\d+)([eE][-+]?\\d+)?$"


## "" when every field of `section` is known and well typed, else the problem (with its line).
static func check_fields(
	section: Dictionary, ext_scripts: Dictionary, sub_classes: Dictionary
) -> String:
	var expected := _property_types(str(section["class"]))
	var fields: Dictionary = section["fields"]
	for key: String in fields:
		var line: int = fields[key][0]
		var value: String = fields[key][1]
		if key in BUILTIN_FIELDS or key.begins_with("metadata/"):
			continue
		var want: Dictionary = expected.get(key, {})
		if (
			want.is_empty()
			and section["class"] == "BoardLevel"
			and BoardUpgrader.LEGACY_FIELDS.has(key)
		):
			want = {"type": BoardUpgrader.LEGACY_FIELDS[key], "class": ""}
		if want.is_empty():
			return "line %d: %s has no field '%s'" % [line, section["class"], key]
		var problem := _check_value(value, want, ext_scripts, sub_classes)
		if not problem.is_empty():
			return "line %d: field '%s' %s" % [line, key, problem]
	return ""


static func _check_value(
	value: String, want: Dictionary, ext_scripts: Dictionary, sub_classes: Dictionary
) -> String:
	var type: int = want["type"]
	var shown := value.left(40).replace("\n", " ")
	if type == TYPE_OBJECT:
		if value == "null":
			return ""
		var id := ref_id(value, "Sub")
		if sub_classes.get(id, "") != want["class"]:
			return "should be a %s, the file has %s" % [want["class"], shown]
		return ""
	if type == TYPE_ARRAY:
		var typed := RegEx.create_from_string(TYPED_ARRAY_PATTERN).search(value)
		var inner := value
		if typed != null:
			if ext_scripts.get(typed.get_string(1), "") != want["class"]:
				return "should be a list of %s" % want["class"]
			inner = typed.get_string(2).strip_edges()
		if not inner.begins_with("[") or not inner.ends_with("]"):
			return "should be a list of %s, the file has %s" % [want["class"], shown]
		for item in inner.substr(1, inner.length() - 2).split(",", false):
			if sub_classes.get(ref_id(item.strip_edges(), "Sub"), "") != want["class"]:
				return (
					"should only hold %s entries, the file has %s"
					% [want["class"], item.strip_edges().left(40)]
				)
		return ""
	var shape_ok := false
	match type:
		TYPE_FLOAT:
			shape_ok = (
				value in ["nan", "inf", "-inf", "inf_neg"]
				or RegEx.create_from_string(NUMBER_PATTERN).search(value) != null
			)
		TYPE_INT:
			shape_ok = value.is_valid_int()
		TYPE_BOOL:
			shape_ok = value == "true" or value == "false"
		TYPE_STRING:
			shape_ok = value.begins_with('"') and value.ends_with('"') and value.length() >= 2
		_:
			shape_ok = (
				CONSTRUCTORS.has(type)
				and value.begins_with(str(CONSTRUCTORS[type]) + "(")
				and value.ends_with(")")
			)
	# Only a value of the right shape reaches str_to_var, which could build any object.
	var parsed: Variant = str_to_var(value) if shape_ok else null
	var got := typeof(parsed)
	if not shape_ok or (got != type and not (type == TYPE_FLOAT and got == TYPE_INT)):
		return "should be %s, the file has %s" % [type_string(type), shown]
	return ""


# Stored properties of a board script: name → {type, class}.
static func _property_types(script_class: String) -> Dictionary:
	var types := {}
	for path: String in ALLOWED_SCRIPTS:
		if ALLOWED_SCRIPTS[path] != script_class:
			continue
		var script: Script = load(path)
		for property in script.get_script_property_list():
			if property["usage"] & PROPERTY_USAGE_STORAGE:
				# A typed array's hint reads "24/17:PocketSpec": element type/hint, then class.
				var hint: String = property["hint_string"]
				var element := hint.get_slice(":", hint.get_slice_count(":") - 1)
				var cls: String = (
					property["class_name"] if property["type"] == TYPE_OBJECT else element
				)
				types[property["name"]] = {"type": property["type"], "class": cls}
	return types


## The id inside `ExtResource("id")` / `SubResource("id")` (by `prefix`), or "".
static func ref_id(value: String, prefix: String) -> String:
	var found := RegEx.create_from_string(REF_PATTERN).search(value.strip_edges())
	if found == null or found.get_string(1) != prefix:
		return ""
	return found.get_string(2)
