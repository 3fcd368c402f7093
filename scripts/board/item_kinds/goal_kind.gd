@tool
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
	return kind
