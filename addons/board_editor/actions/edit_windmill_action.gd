@tool
extends BoardAction
## Sets one field of a windmill (WindmillSpec): its blade count, blade length, whether it
## spins free (1) or is driven (0), a driven wheel's speed or a free wheel's friction. One
## field, one undo step; the property panel makes one per edit.

## Field key -> [WindmillSpec property, whole number].
const FIELDS := {
	"blades": ["blades", true],
	"length": ["length", false],
	"free": ["free_spin", true],
	"speed": ["speed", false],
	"friction": ["friction", false],
}

var _index: int
var _field: String
var _value: float


func _init(on_level: BoardLevel, index: int, field: String, value: float) -> void:
	super(on_level)
	_index = index
	_field = field
	_value = value


func get_name() -> String:
	return "Set windmill %s" % _field


func _touched_fields() -> PackedStringArray:
	return PackedStringArray(["windmills"])


func _apply() -> void:
	if _index < 0 or _index >= level.windmills.size() or not FIELDS.has(_field):
		push_error("Edit windmill: no windmill %d or field '%s'." % [_index, _field])
		return
	var spec := level.windmills[_index]
	var entry: Array = FIELDS[_field]
	var property: String = entry[0]
	if _field == "free":
		spec.free_spin = _value >= 0.5
	elif entry[1]:
		spec.set(property, roundi(_value))
	else:
		spec.set(property, _value)
