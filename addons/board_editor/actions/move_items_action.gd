@tool
extends BoardAction
## Moves items by an offset: a pocket takes its rim pins along, a wall both ends, a bonus
## pocket its whole cup (its pins are stamped from its mouth). In mirror
## mode the partners move by the reflected offset and items on the axis only vertically.
## A drag calls `preview()` on every mouse move and is committed once on release.

const BoardItems := preload("res://addons/board_editor/core/board_items.gd")

## The offset applied to the direct items.
var delta := Vector2.ZERO
var _direct: Array[Vector2i]
var _mirrored: Array[Vector2i]
var _on_axis: Array[Vector2i]


func _init(
	on_level: BoardLevel,
	items: Array[Vector2i],
	offset: Vector2,
	mirrored: Array[Vector2i] = [],
	on_axis: Array[Vector2i] = []
) -> void:
	super(on_level)
	_direct = items.duplicate()
	_mirrored = mirrored.duplicate()
	_on_axis = on_axis.duplicate()
	delta = offset


func get_name() -> String:
	return "Move %d board item%s" % [item_count(), "" if item_count() == 1 else "s"]


## How many items move.
func item_count() -> int:
	return _direct.size() + _mirrored.size() + _on_axis.size()


## Re-applies the move with a new offset (live drag preview).
func preview(offset: Vector2) -> void:
	if is_applied():
		undo()
	delta = offset
	do()


func _touched_fields() -> PackedStringArray:
	return BoardItems.position_fields()


func _apply() -> void:
	# One copy per packed field, handed back at the end (ItemEdits.working).
	var work := {}
	var groups: Array = [
		[_direct, delta], [_mirrored, Vector2(-delta.x, delta.y)], [_on_axis, Vector2(0, delta.y)]
	]
	for group: Array in groups:
		var offset: Vector2 = group[1]
		for item: Vector2i in group[0]:
			var kind := ItemKinds.of_item(level, item)
			if kind != null and kind.is_valid(level, item.y):
				ItemEdits.offset(kind, level, work, item.y, offset)
	ItemEdits.store(level, work)
