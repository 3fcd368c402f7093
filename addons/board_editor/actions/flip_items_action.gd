@tool
extends BoardAction
## Flips items left to right, each group about its own vertical line, in one undo step:
## pins, holes, starts and the goal land at their reflection, a wall's two ends are
## reflected, a pocket or bonus pocket moves its mouth there (its cup is symmetrical, so its
## rim pins move with it) and a windmill turns the other way. Items keep their ids.
## Flipping a selection in mirror mode is two groups: the selection about its centre, and
## the selection's twins about the reflected centre, so the board stays symmetrical.

const BoardItems := preload("res://addons/board_editor/core/board_items.gd")

var _groups: Array = []
var _count := 0


## `groups` is a list of [items (Array[Vector2i]), axis x (float)]: each group's items are
## reflected across the vertical line x = axis.
func _init(on_level: BoardLevel, groups: Array) -> void:
	super(on_level)
	for group: Array in groups:
		var items: Array[Vector2i] = group[0]
		var axis: float = group[1]
		_groups.append([items.duplicate(), axis])
		_count += items.size()


func get_name() -> String:
	return "Flip %d item%s left to right" % [_count, "" if _count == 1 else "s"]


func _touched_fields() -> PackedStringArray:
	return BoardItems.position_fields()


func _apply() -> void:
	# One copy per packed field, handed back at the end (ItemEdits.working).
	var work := {}
	for group: Array in _groups:
		var axis: float = group[1]
		for item: Vector2i in group[0]:
			var kind := ItemKinds.of_item(level, item)
			if kind != null and kind.is_valid(level, item.y):
				ItemEdits.reflect_item(kind, level, work, item.y, axis)
	ItemEdits.store(level, work)
