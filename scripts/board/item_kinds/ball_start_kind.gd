@tool
class_name BallStartKind
extends RefCounted
## Ball starts: where a maze's balls start, one ball per point in `BoardLevel.ball_starts`.


## The ball start row of ItemKinds.
static func row() -> ItemKind:
	var kind := ItemKind.make("ball_start", "ball_starts", ItemKind.Shape.POINT)
	kind.list = "ball_starts"
	kind.id_field = "start_ids"
	kind.game = BoardLevel.Kind.MAZE
	kind.pick = ItemKind.Pick.START
	kind.singular = "Ball start"
	kind.plural = "Ball starts"
	kind.set_key = "starts"
	kind.max_items = 64
	kind.size_field = "ball_radius"
	kind.layer = "Ball starts"
	kind.paint_layer = "STARTS"
	kind.placed_by_click = true
	kind.optional_file_fields = {"id": ["int", 1, ItemKind.MAX_ID]}
	return kind
