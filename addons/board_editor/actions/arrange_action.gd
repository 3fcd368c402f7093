@tool
extends BoardAction
## Moves several items each by its own offset in one undo step (align and distribute).
## Each item moves as a drag would move it: a pocket with its rim pins, a wall with both ends.

const MoveItemsAction := preload("res://addons/board_editor/actions/move_items_action.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")

var _offsets: Dictionary
var _name: String


## `offsets` maps items (BoardItems) to how far each moves.
func _init(on_level: BoardLevel, offsets: Dictionary, action_name: String) -> void:
	super(on_level)
	_offsets = offsets.duplicate()
	_name = action_name


func get_name() -> String:
	return _name


func _touched_fields() -> PackedStringArray:
	return BoardItems.position_fields()


func _apply() -> void:
	for item: Vector2i in _offsets:
		var offset: Vector2 = _offsets[item]
		var move := MoveItemsAction.new(level, [item] as Array[Vector2i], offset)
		move.do()
