@tool
class_name GoalKind
extends RefCounted
## The goal: a maze's one goal ring (`BoardLevel.goal_center`). It is a board field, not an
## item line: it has no id, can be moved and mirrored but never added or deleted.


## The goal row of ItemKinds.
static func row() -> ItemKind:
	var kind := ItemKind.make("goal", "goal_center", ItemKind.Shape.SINGLE)
	kind.list = "goal"
	kind.game = BoardLevel.Kind.MAZE
	kind.pick = ItemKind.Pick.GOAL
	kind.singular = "Goal"
	kind.plural = "Goals"
	kind.item_fields = PackedStringArray()
	kind.file_fields = {}
	kind.pick_rank = ItemKind.PickRank.LAST
	kind.erasable = false
	kind.layer = "Goal"
	kind.paint_layer = "GOAL"
	kind.placed_by_click = true
	kind.outlines = _ring
	kind.properties = _fields
	kind.edits = _set_radius
	kind.edit_fields = PackedStringArray(["goal_radius"])
	return kind


static func _set_radius(level: BoardLevel, _index: int, key: String, value: float) -> void:
	if key == "radius":
		level.goal_radius = value


# The goal is big: only its middle picks it, so walls and starts inside stay reachable.
static func _ring(level: BoardLevel, at: Vector2) -> ItemOutline:
	var ring := ItemOutline.circle(at, level.goal_radius)
	ring.core = 0.35
	ring.hollow = true
	ring.line_width = 2.5
	return ring


static func _fields(level: BoardLevel, _index: int) -> Dictionary:
	return {"x": level.goal_center.x, "y": level.goal_center.y, "radius": level.goal_radius}
