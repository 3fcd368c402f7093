@tool
class_name WallKind
extends RefCounted
## Maze walls: capsules between two points a, b, stored as pairs in `BoardLevel.walls`.


## The wall row of ItemKinds.
static func row() -> ItemKind:
	var kind := ItemKind.make("wall", "walls", ItemKind.Shape.SEGMENT)
	kind.list = "walls"
	kind.id_field = "wall_ids"
	kind.game = BoardLevel.Kind.MAZE
	kind.pick = ItemKind.Pick.WALL
	kind.singular = "Wall"
	kind.plural = "Walls"
	kind.set_key = "walls"
	kind.max_items = 4000
	kind.size_field = "wall_width"
	kind.pick_rank = ItemKind.PickRank.UNDER  # a start, hole or pin drawn over it wins inside
	kind.layer = "Walls"
	kind.paint_layer = "WALLS"
	kind.file_fields = {"ax": ["coord"], "ay": ["coord"], "bx": ["coord"], "by": ["coord"]}
	kind.optional_file_fields = {"id": ["int", 1, ItemKind.MAX_ID]}
	return kind
