@tool
extends RefCounted
## What the property panel shows and edits for a selection of one item: exact x / y for
## pins, holes, starts and the goal; a pocket's mouth, width, depth and payout; a wall's two
## ends; the goal's radius; a bonus pocket's mouth, size and payout, and per role its reel
## symbols (start pocket) or how long and for how many catches it opens (attacker); a
## windmill's pin, blades, length, and its speed (driven) or friction (free). Each field
## edit becomes one action (one undo step). With several items selected, the fields they
## all have, each with their common value or MIXED; a value typed there lands on all of them
## in one undo step (action_for_all).

const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const MoveItemsAction := preload("res://addons/board_editor/actions/move_items_action.gd")
const SetPointAction := preload("res://addons/board_editor/actions/set_point_action.gd")
const SetPropertiesAction := preload("res://addons/board_editor/actions/set_properties_action.gd")
const Mirror := preload("res://addons/board_editor/core/mirror.gd")
const ItemGroupAction := preload("res://addons/board_editor/actions/item_group_action.gd")
const EditItemAction := preload("res://addons/board_editor/actions/edit_item_action.gd")
## The value shared_values gives a field the items disagree on.
const MIXED := NAN

## Field key -> [label, lowest, highest, arrow step, whole numbers only]; values keep the
## board file's 0.01 px precision (NumberRow).
const FIELDS := {
	"x": ["x (px)", -50.0, 2000.0, 0.5],
	"y": ["y (px)", -50.0, 2000.0, 0.5],
	"ax": ["End A x (px)", -50.0, 2000.0, 0.5],
	"ay": ["End A y (px)", -50.0, 2000.0, 0.5],
	"bx": ["End B x (px)", -50.0, 2000.0, 0.5],
	"by": ["End B y (px)", -50.0, 2000.0, 0.5],
	"width": ["Width (px)", 4.0, 200.0, 1.0],
	"depth": ["Depth (px)", 4.0, 200.0, 1.0],
	"payout": ["Payout (balls)", 0.0, 99.0, 1.0, true],
	"radius": ["Radius (px)", 6.0, 200.0, 0.5],
	"symbols": ["Reel symbols", 2.0, 9.0, 1.0, true],
	"open_seconds": ["Opens for (s)", 1.0, 30.0, 0.5],
	"open_catches": ["Closes after (catches)", 1.0, 50.0, 1.0, true],
	"blades": ["Blades", 2.0, 12.0, 1.0, true],
	"length": ["Blade length (px)", 8.0, 120.0, 0.5],
	"free": ["Spins free (1) or driven (0)", 0.0, 1.0, 1.0, true],
	"speed": ["Speed (degrees/s, + clockwise)", -3600.0, 3600.0, 5.0],
	"friction": ["Friction (degrees/s²)", 0.0, 36000.0, 5.0],
}


## The editable fields of `item` in display order, with their current values (its row's
## `properties` hook; a point's x and y, a wall's two ends).
static func values_of(level: BoardLevel, item: Vector2i) -> Dictionary:
	if not BoardItems.is_valid(level, item):
		return {}
	var kind := ItemKinds.of_item(level, item)
	if kind.properties.is_valid():
		return kind.properties.call(level, item.y)
	if kind.shape == ItemKind.Shape.SEGMENT:
		var ends: PackedVector2Array = level.get(kind.field)
		var a := ends[item.y * 2]
		var b := ends[item.y * 2 + 1]
		return {"ax": a.x, "ay": a.y, "bx": b.x, "by": b.y}
	var at := kind.position_of(level, item.y)
	return {"x": at.x, "y": at.y}


## The action that sets field `key` of `item` to `value`, or null when nothing changes.
static func action_for(level: BoardLevel, item: Vector2i, key: String, value: float) -> BoardAction:
	var now := values_of(level, item)
	var current: float = now.get(key, NAN)
	if not now.has(key) or is_equal_approx(current, value):
		return null
	var kind := ItemKinds.of_item(level, item)
	if key in ["x", "y"]:
		return _place_action(level, kind, item, key, value)
	if kind.shape == ItemKind.Shape.SEGMENT:
		var end := item.y * 2 + (1 if key.begins_with("b") else 0)
		var ends: PackedVector2Array = level.get(kind.field)
		var point := ends[end]
		point = Vector2(value, point.y) if key.ends_with("x") else Vector2(point.x, value)
		var named := "Set %s end" % kind.singular.to_lower()
		return SetPointAction.new(level, kind.field, end, point, named)
	return EditItemAction.new(level, kind, item.y, key, value) if kind.edits.is_valid() else null


# The action that puts `item` at a new x or y: a point is set, the goal's field too, a
# resource moves (a pocket with its rim pins).
static func _place_action(
	level: BoardLevel, kind: ItemKind, item: Vector2i, key: String, value: float
) -> BoardAction:
	var at := BoardItems.position_of(level, item)
	var target := Vector2(value, at.y) if key == "x" else Vector2(at.x, value)
	match kind.shape:
		ItemKind.Shape.POINT:
			var named := "Set %s position" % kind.singular.to_lower()
			return SetPointAction.new(level, kind.field, item.y, target, named)
		ItemKind.Shape.SINGLE:
			var moved := "Set %s position" % kind.singular.to_lower()
			return SetPropertiesAction.new(level, {kind.field: target}, moved)
	return MoveItemsAction.new(level, [item] as Array[Vector2i], target - at)


## The action that sets x or y of `item` in mirror mode (axis x `axis`): its mirror twin
## moves with it, as a drag moves both; null when the item has no twin (then `action_for`).
static func mirrored_action_for(
	level: BoardLevel, item: Vector2i, key: String, value: float, axis: float
) -> BoardAction:
	if not key in ["x", "y"] or not BoardItems.is_valid(level, item):
		return null
	var shape := ItemKinds.of_item(level, item).shape
	if shape == ItemKind.Shape.SINGLE or shape == ItemKind.Shape.SEGMENT:
		return null
	var twin := Mirror.partner(level, item, axis)
	if twin == BoardItems.NONE or twin == item:
		return null
	var at := BoardItems.position_of(level, item)
	var target := Vector2(value, at.y) if key == "x" else Vector2(at.x, value)
	if target == at:
		return null
	var split := Mirror.split_for_move(level, [item] as Array[Vector2i], axis, at.x)
	var direct: Array[Vector2i] = split["direct"]
	var mirrored: Array[Vector2i] = split["mirrored"]
	var on_axis: Array[Vector2i] = split["on_axis"]
	return MoveItemsAction.new(level, direct, target - at, mirrored, on_axis)


## The fields every one of `items` has, in display order, each with the value they share or
## MIXED where they differ ({} for no items).
static func shared_values(level: BoardLevel, items: Array[Vector2i]) -> Dictionary:
	if items.is_empty():
		return {}
	var shared := values_of(level, items[0])
	for i in range(1, items.size()):
		var values := values_of(level, items[i])
		for key: String in shared.keys():
			if not values.has(key):
				shared.erase(key)
				continue
			var mine: float = shared[key]
			var theirs: float = values[key]
			if not is_nan(mine) and not is_equal_approx(mine, theirs):
				shared[key] = MIXED
	return shared


## The one action (one undo step) that sets field `key` to `value` on every item of
## `items` that has it, or null when none would change. With mirror mode on (`axis` a
## number), each item's mirror twin follows: for x and y as a drag moves both halves (a
## selected twin is left to its partner), for other fields by taking the same value.
static func action_for_all(
	level: BoardLevel, items: Array[Vector2i], key: String, value: float, axis := NAN
) -> BoardAction:
	var targets := _targets(level, items, key, axis)
	var changes := targets.filter(
		func(item: Vector2i) -> bool: return action_for(level, item, key, value) != null
	)
	if changes.is_empty():
		return null
	var build := func(board: BoardLevel, item: Vector2i) -> BoardAction:
		var mirrored: BoardAction = null
		if not is_nan(axis):
			mirrored = mirrored_action_for(board, item, key, value, axis)
		return mirrored if mirrored != null else action_for(board, item, key, value)
	var label: String = FIELDS[key][0]
	var field_name := label.get_slice(" (", 0).to_lower()
	var action_name := "Set %s of %d items" % [field_name, targets.size()]
	return ItemGroupAction.new(level, targets, build, action_name)


# The items a field edit reaches: `items`, less a twin whose partner moves it (x, y), plus
# the twins that take the same value (other fields), each once.
static func _targets(
	level: BoardLevel, items: Array[Vector2i], key: String, axis: float
) -> Array[Vector2i]:
	var targets: Array[Vector2i] = []
	for item in items:
		if not values_of(level, item).has(key) or targets.has(item):
			continue
		var twin := BoardItems.NONE if is_nan(axis) else Mirror.partner(level, item, axis)
		var moves_twin := key in ["x", "y"] and twin != BoardItems.NONE
		if moves_twin and targets.has(twin):
			continue  # its partner's edit moves it
		targets.append(item)
		if not key in ["x", "y"] and twin != BoardItems.NONE and not targets.has(twin):
			targets.append(twin)
	return targets
