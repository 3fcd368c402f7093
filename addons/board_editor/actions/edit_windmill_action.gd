@tool
extends "res://addons/board_editor/actions/edit_spec_field_action.gd"
## Sets one field of a windmill (WindmillSpec): its blade count, blade length, whether it
## spins free (1) or is driven (0), a driven wheel's speed or a free wheel's friction. One
## field, one undo step; the property panel makes one per edit.

## Field key -> WindmillSpec property.
const FIELDS := {
	"blades": "blades",
	"length": "length",
	"free": "free_spin",
	"speed": "speed",
	"friction": "friction",
}

var _field: String


func _init(on_level: BoardLevel, index: int, field: String, value: float) -> void:
	var property: String = FIELDS.get(field, "")
	super(on_level, "windmills", index, property, value)
	_field = field


func get_name() -> String:
	return "Set windmill %s" % _field
