@tool
extends BoardAction
## Removes items: pins, pockets (with their rim pins; the other pins' pocket indices are
## renumbered), walls, holes, ball starts, bonus pockets and windmills: each pick's
## ItemKinds row removes its own. The goal cannot be removed, only moved.

const BoardItems := preload("res://addons/board_editor/core/board_items.gd")

var _items: Array[Vector2i]


func _init(on_level: BoardLevel, items: Array[Vector2i]) -> void:
	super(on_level)
	_items = items.duplicate()


func get_name() -> String:
	return "Delete %d board item%s" % [_items.size(), "" if _items.size() == 1 else "s"]


func _touched_fields() -> PackedStringArray:
	return BoardItems.item_fields()


func _apply() -> void:
	# In table order, pins before pockets: a pocket's removal drops its rim pins by owner,
	# which leaves the indices of the pins removed before it alone.
	var work := {}
	for kind in ItemKinds.pick_rows():
		var gone := PackedInt32Array()
		for index in BoardItems.indices_of(_items, kind.pick):
			if BoardItems.is_valid(level, BoardItems.make(kind.pick, index)):
				gone.append(index)
		ItemEdits.remove(kind, level, work, gone)
	ItemEdits.store(level, work)
