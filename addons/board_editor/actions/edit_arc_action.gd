@tool
extends BoardAction
## Reshapes a pin arc in one undo step (the Selection panel's arc fields): the arc's pins,
## in arc order, move to the new arc's points; pins the new arc no longer needs are removed
## and pins it needs more of are added after the board's other pins. With the count kept,
## every pin keeps its id.

const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const PinArc := preload("res://addons/board_editor/core/pin_arc.gd")

## The arc's pins after the last `do()`, start to end, for the editor to select.
var selected: Array[Vector2i] = []
var _pins: PackedInt32Array
var _arc: Dictionary


## `pins`: the arc's pin indices from start to end (PinArc.of_selection); `arc`: the new
## shape (PinArc.KEYS).
func _init(on_level: BoardLevel, pins: PackedInt32Array, arc: Dictionary) -> void:
	super(on_level)
	_pins = pins.duplicate()
	_arc = arc.duplicate()


func get_name() -> String:
	return "Edit pin arc"


func _touched_fields() -> PackedStringArray:
	return PackedStringArray(["pins", "pin_pocket", "pin_special"])


func _apply() -> void:
	var target := PinArc.points_of(_arc)
	if target.is_empty():
		push_error("Edit pin arc: the new arc has no pins (count %s)." % str(_arc.get("count")))
		return
	var kept := mini(target.size(), _pins.size())
	var pins := level.pins.duplicate()
	var pin_pocket := level.pin_pocket.duplicate()
	var pin_special := level.pin_special.duplicate()
	pin_pocket.resize(pins.size())
	pin_special.resize(pins.size())
	var arc_index := {}  # pin index -> place on the arc
	for k in kept:
		pins[_pins[k]] = target[k]
		arc_index[_pins[k]] = k
	# Pins the smaller arc no longer needs go; the others keep their order.
	var gone := {}
	for k in range(kept, _pins.size()):
		gone[_pins[k]] = true
	var new_pins := PackedVector2Array()
	var new_pocket := PackedInt32Array()
	var new_special := PackedByteArray()
	var placed: Array[Vector2i] = []
	placed.resize(target.size())
	for i in pins.size():
		if gone.has(i):
			continue
		if arc_index.has(i):
			var k: int = arc_index[i]
			placed[k] = BoardItems.make(BoardItems.Kind.PIN, new_pins.size())
		new_pins.append(pins[i])
		new_pocket.append(pin_pocket[i] if i < level.pin_pocket.size() else -1)
		new_special.append(pin_special[i])
	for k in range(kept, target.size()):
		placed[k] = BoardItems.make(BoardItems.Kind.PIN, new_pins.size())
		new_pins.append(target[k])
		new_pocket.append(-1)
		new_special.append(0)
	level.pins = new_pins
	level.pin_pocket = new_pocket
	level.pin_special = new_special
	selected = placed
