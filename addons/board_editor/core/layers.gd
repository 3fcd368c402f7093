@tool
extends RefCounted
## The editor's layers: each groups one kind of item with the parts of the board drawing
## that show it. A hidden layer is not drawn and cannot be picked; a locked one is drawn but
## cannot be picked, moved or erased (placing new items is still possible).

const Items := preload("res://addons/board_editor/core/board_items.gd")

## Layer name -> [item kind or -1, BoardPainter layer flags, board kind or -1 for both].
const LAYERS := {
	"Pins": [Items.Kind.PIN, BoardPainter.Layer.PINS, BoardLevel.Kind.PACHINKO],
	"Pockets": [Items.Kind.POCKET, BoardPainter.Layer.POCKETS, BoardLevel.Kind.PACHINKO],
	"Bonus pieces": [Items.Kind.BONUS, BoardPainter.Layer.BONUS, BoardLevel.Kind.PACHINKO],
	"Windmills": [Items.Kind.WINDMILL, BoardPainter.Layer.WINDMILLS, BoardLevel.Kind.PACHINKO],
	"Rail and gutter":
	[-1, BoardPainter.Layer.RAIL | BoardPainter.Layer.GUTTER, BoardLevel.Kind.PACHINKO],
	"Walls": [Items.Kind.WALL, BoardPainter.Layer.WALLS, BoardLevel.Kind.MAZE],
	"Holes": [Items.Kind.HOLE, BoardPainter.Layer.HOLES, BoardLevel.Kind.MAZE],
	"Ball starts": [Items.Kind.START, BoardPainter.Layer.STARTS, BoardLevel.Kind.MAZE],
	"Goal": [Items.Kind.GOAL, BoardPainter.Layer.GOAL, BoardLevel.Kind.MAZE],
}


## The layers a board of `kind` has, in display order.
static func for_kind(kind: int) -> Array[String]:
	var names: Array[String] = []
	for layer: String in LAYERS:
		var entry: Array = LAYERS[layer]
		var board_kind: int = entry[2]
		if board_kind == kind:
			names.append(layer)
	return names


## The layer an item belongs to ("" for none).
static func of_item(item: Vector2i) -> String:
	for layer: String in LAYERS:
		var entry: Array = LAYERS[layer]
		var item_kind: int = entry[0]
		if item_kind == item.x:
			return layer
	return ""


## The BoardPainter flags of the `hidden` layers (what the board node leaves out).
static func painter_mask(hidden: Array[String]) -> int:
	var mask := 0
	for layer in hidden:
		var entry: Array = LAYERS.get(layer, [-1, 0])
		var flags: int = entry[1]
		mask |= flags
	return mask
