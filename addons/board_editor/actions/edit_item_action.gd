@tool
extends BoardAction
## Sets one property (not its place) of one item through its row's `edits` hook
## (ItemKind.edits): the property panel's edit of a pocket's size, a windmill's blades, the
## goal's radius..., one undo step that snapshots the fields the row names.

var _kind: ItemKind
var _index: int
var _key: String
var _value: float


## Sets property `key` of item `index` of `kind` to `value`.
func _init(on_level: BoardLevel, kind: ItemKind, index: int, key: String, value: float) -> void:
	super(on_level)
	_kind = kind
	_index = index
	_key = key
	_value = value


func get_name() -> String:
	return "Set %s %s" % [_kind.singular.to_lower(), _key.replace("_", " ")]


func _touched_fields() -> PackedStringArray:
	return _kind.item_fields + _kind.edit_fields


func _apply() -> void:
	if not _kind.is_item(level, _index):
		push_error("%s: the board has no %s %d." % [get_name(), _kind.singular.to_lower(), _index])
		return
	_kind.edits.call(level, _index, _key, _value)
