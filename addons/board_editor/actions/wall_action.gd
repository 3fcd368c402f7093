@tool
extends "res://addons/board_editor/actions/add_items_action.gd"
## Adds one maze wall (a capsule from `a` to `b`), mirrored when asked.

const Mirror := preload("res://addons/board_editor/core/mirror.gd")


## `mirror_axis` is NAN for no mirror.
func _init(on_level: BoardLevel, a: Vector2, b: Vector2, mirror_axis: float = NAN) -> void:
	var data := BoardItems.empty_set()
	data["walls"] = PackedVector2Array([a, b])
	if not is_nan(mirror_axis):
		data = Mirror.mirror_set(data, mirror_axis)
	super(on_level, data, "Add wall")
