@tool
extends BoardAction
## Sets one field of one item the board keeps as a Resource in a list (a windmill in
## `windmills`, a bonus pocket in `bonus_pockets`): the Selection panel makes one per typed
## value, one undo step. The value is typed as a number and stored as the property's own
## type: a whole number rounded, a yes/no from 0 or 1.

var _list: String
var _index: int
var _property: String
var _value: float


## Sets `property` of the item at `index` in the board's list `list` to `value`.
func _init(on_level: BoardLevel, list: String, index: int, property: String, value: float) -> void:
	super(on_level)
	_list = list
	_index = index
	_property = property
	_value = value


func _touched_fields() -> PackedStringArray:
	return PackedStringArray([_list])


func _apply() -> void:
	var items: Array = level.get(_list)
	var spec: Resource = items[_index] if _index >= 0 and _index < items.size() else null
	if spec == null or _property.is_empty() or not _property in spec:
		push_error("%s: no item %d in %s or field '%s'." % [get_name(), _index, _list, _property])
		return
	var current: Variant = spec.get(_property)
	if current is bool:
		spec.set(_property, _value >= 0.5)
	elif current is int:
		spec.set(_property, roundi(_value))
	else:
		spec.set(_property, _value)
