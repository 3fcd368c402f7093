@tool
class_name HoleKind
extends RefCounted
## Black holes: a maze's traps (hard mode only), one centre each in `BoardLevel.holes`.


## The black hole row of ItemKinds.
static func row() -> ItemKind:
	var kind := ItemKind.make("hole", "holes", ItemKind.Shape.POINT)
	kind.list = "holes"
	kind.id_field = "hole_ids"
	kind.game = BoardLevel.Kind.MAZE
	kind.pick = ItemKind.Pick.HOLE
	kind.singular = "Black hole"
	kind.plural = "Black holes"
	kind.set_key = "holes"
	kind.max_items = 500
	kind.size_field = "hole_radius"
	kind.layer = "Holes"
	kind.paint_layer = "HOLES"
	kind.placed_by_click = true
	kind.optional_file_fields = {"id": ["int", 1, ItemKind.MAX_ID]}
	return kind
