@tool
extends RefCounted
## The editor's layers: each groups one kind of item with the parts of the board drawing
## that show it. A hidden layer is not drawn and cannot be picked; a locked one is drawn but
## cannot be picked, moved or erased (placing new items is still possible).

const BoardItems := preload("res://addons/board_editor/core/board_items.gd")

## The layers that hold no items, per board kind: name -> BoardPainter layer flags. They
## follow the item layers (ItemKinds.layers_of, from the rows) in the list.
const PARTS := {
	BoardLevel.Kind.PACHINKO:
	{"Rail and gutter": BoardPainter.Layer.RAIL | BoardPainter.Layer.GUTTER},
	BoardLevel.Kind.MAZE: {},
}


## The layers a board of `kind` has, in display order: its item kinds' (table order), then
## its parts'.
static func for_kind(kind: int) -> Array[String]:
	var names: Array[String] = []
	names.assign(ItemKinds.layers_of(kind).keys())
	var parts: Dictionary = PARTS.get(kind, {})
	names.append_array(parts.keys())
	return names


## The layer an item belongs to ("" for none).
static func of_item(item: Vector2i) -> String:
	var kind := ItemKinds.of_pick(item.x)
	return kind.layer if kind != null else ""


## The BoardPainter flags of the `hidden` layers (what the board node leaves out).
static func painter_mask(hidden: Array[String]) -> int:
	var mask := 0
	for layer in hidden:
		mask |= _flags_of(layer)
	return mask


# The BoardPainter flags of layer `layer` (0 for an unknown name).
static func _flags_of(layer: String) -> int:
	for game: int in PARTS:
		var parts: Dictionary = PARTS[game]
		if parts.has(layer):
			return parts[layer]
		var items := ItemKinds.layers_of(game)
		if items.has(layer):
			return BoardPainter.Layer[items[layer]]
	return 0
