@tool
extends BoardAction
## Sets board fields to new values: the ring and launch-rail handles, the goal, board
## settings. A handle drag calls `preview()` while moving and is committed once.

var _values: Dictionary
var _name: String


## `values` maps BoardLevel field names to their new values.
func _init(on_level: BoardLevel, values: Dictionary, action_name := "Change board") -> void:
	super(on_level)
	_values = values.duplicate()
	_name = action_name


func get_name() -> String:
	return _name


## Re-applies the action with new values for the same fields (live drag preview).
func preview(values: Dictionary) -> void:
	if is_applied():
		undo()
	for key: String in values:
		_values[key] = values[key]
	do()


func _touched_fields() -> PackedStringArray:
	var fields := PackedStringArray()
	for key: String in _values:
		if not key in level:
			push_error("Board edit: the board has no field '%s'." % key)
			continue
		fields.append(key)
	return fields


func _apply() -> void:
	for key in _touched_fields():
		level.set(key, _values[key])
