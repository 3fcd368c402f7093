@tool
extends RefCounted
## How the editor names an item to a designer: by kind and stable id ("Pin 143"), the same
## id the problem messages and the board file use (ItemIds).

const Items := preload("res://addons/board_editor/core/board_items.gd")

## Item kind -> [name, item list].
const KINDS := {
	Items.Kind.PIN: ["Pin", "pins"],
	Items.Kind.POCKET: ["Pocket", "pockets"],
	Items.Kind.WALL: ["Wall", "walls"],
	Items.Kind.HOLE: ["Black hole", "holes"],
	Items.Kind.START: ["Ball start", "ball_starts"],
	Items.Kind.WINDMILL: ["Windmill", "windmills"],
}


## "Pin 143", "Wall 12", "Tulip 3", "Goal".
static func name_of(level: BoardLevel, item: Vector2i) -> String:
	if item.x == Items.Kind.BONUS and Items.is_valid(level, item):
		var spec := level.bonus_pockets[item.y]
		return "%s %d" % [spec.role_name(), ItemIds.of_bonus(level, item.y)]
	if not KINDS.has(item.x):
		return "Goal"
	var entry: Array = KINDS[item.x]
	var list: String = entry[1]
	return "%s %d" % [entry[0], ItemIds.of(level, list, item.y)]


## "Pin 143 at (255, 84)": the property panel's heading.
static func title(level: BoardLevel, item: Vector2i) -> String:
	if not Items.is_valid(level, item):
		return ""
	var at := Items.position_of(level, item)
	return "%s at (%s, %s)" % [name_of(level, item), _number(at.x), _number(at.y)]


static func _number(value: float) -> String:
	return str(snappedf(value, 0.01)).trim_suffix(".0")
