@tool
extends RefCounted
## How the editor names an item to a designer: by kind and stable id ("Pin 143"), the same
## id the problem messages and the board file use (ItemIds). The words are each kind's
## ItemKinds row's.

const BoardItems := preload("res://addons/board_editor/core/board_items.gd")


## "Pin 143", "Wall 12", "Tulip 3", "Goal".
static func name_of(level: BoardLevel, item: Vector2i) -> String:
	var kind := ItemKinds.of_item(level, item)
	if kind == null:
		return "Goal"  # names no item: as before the table, the one item without an id
	if not kind.has_ids():
		return kind.singular
	if kind.shape == ItemKind.Shape.ROLE_SPEC:
		return "%s %d" % [kind.singular, ItemIds.of_bonus(level, item.y)]
	return "%s %d" % [kind.singular, ItemIds.of(level, kind.list, item.y)]


## "Pin 143 at (255, 84)": the property panel's heading.
static func title(level: BoardLevel, item: Vector2i) -> String:
	if not BoardItems.is_valid(level, item):
		return ""
	var at := BoardItems.position_of(level, item)
	return "%s at (%s, %s)" % [name_of(level, item), _number(at.x), _number(at.y)]


static func _number(value: float) -> String:
	return str(snappedf(value, 0.01)).trim_suffix(".0")
