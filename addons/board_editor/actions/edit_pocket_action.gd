@tool
extends BoardAction
## Changes a pocket's width, depth and payout and stamps its rim pins and special pin again
## so the pins always match the numbers in the inspector.

const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const PocketPins := preload("res://addons/board_editor/core/pocket_pins.gd")

var _index: int
var _width: float
var _depth: float
var _payout: int


func _init(
	on_level: BoardLevel, pocket_index: int, width: float, depth: float, payout: int
) -> void:
	super(on_level)
	_index = pocket_index
	_width = width
	_depth = depth
	_payout = payout


func get_name() -> String:
	return "Edit pocket"


func _touched_fields() -> PackedStringArray:
	return PackedStringArray(["pins", "pin_pocket", "pin_special", "pockets"])


func _apply() -> void:
	if _index < 0 or _index >= level.pockets.size():
		push_error("Edit pocket: the board has no pocket %d." % _index)
		return
	var spec: PocketSpec = level.pockets[_index]
	spec.width = _width
	spec.depth = _depth
	spec.payout = _payout
	var pins := PackedVector2Array()
	var pin_pocket := PackedInt32Array()
	var pin_special := PackedByteArray()
	for i in level.pins.size():
		var owner := level.pin_pocket[i] if i < level.pin_pocket.size() else -1
		if owner == _index:
			continue
		pins.append(level.pins[i])
		pin_pocket.append(owner)
		pin_special.append(level.pin_special[i] if i < level.pin_special.size() else 0)
	var stamp := PocketPins.stamp(level, spec)
	var stamped: PackedVector2Array = stamp["pins"]
	var special: PackedByteArray = stamp["special"]
	for j in stamped.size():
		pins.append(stamped[j])
		pin_pocket.append(_index)
		pin_special.append(special[j])
	level.pins = pins
	level.pin_pocket = pin_pocket
	level.pin_special = pin_special
