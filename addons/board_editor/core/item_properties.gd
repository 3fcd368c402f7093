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

const Items := preload("res://addons/board_editor/core/board_items.gd")
const MoveItemsAction := preload("res://addons/board_editor/actions/move_items_action.gd")
const SetPointAction := preload("res://addons/board_editor/actions/set_point_action.gd")
const EditPocketAction := preload("res://addons/board_editor/actions/edit_pocket_action.gd")
const SetPropertiesAction := preload("res://addons/board_editor/actions/set_properties_action.gd")
const BonusActions := preload("res://addons/board_editor/bonus/bonus_actions.gd")
const Mirror := preload("res://addons/board_editor/core/mirror.gd")
const EditWindmillAction := preload("res://addons/board_editor/actions/edit_windmill_action.gd")
const ItemGroupAction := preload("res://addons/board_editor/actions/item_group_action.gd")
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
const POINT_FIELD := {
	Items.Kind.PIN: "pins", Items.Kind.HOLE: "holes", Items.Kind.START: "ball_starts"
}


## The editable fields of `item` in display order, with their current values.
static func values_of(level: BoardLevel, item: Vector2i) -> Dictionary:
	if not Items.is_valid(level, item):
		return {}
	var at := Items.position_of(level, item)
	match item.x:
		Items.Kind.POCKET:
			var spec: PocketSpec = level.pockets[item.y]
			return {
				"x": at.x,
				"y": at.y,
				"width": spec.width,
				"depth": spec.depth,
				"payout": float(spec.payout)
			}
		Items.Kind.WALL:
			var a := level.walls[item.y * 2]
			var b := level.walls[item.y * 2 + 1]
			return {"ax": a.x, "ay": a.y, "bx": b.x, "by": b.y}
		Items.Kind.GOAL:
			return {"x": at.x, "y": at.y, "radius": level.goal_radius}
		Items.Kind.BONUS:
			return _bonus_values(level.bonus_pockets[item.y])
		Items.Kind.WINDMILL:
			return _windmill_values(level.windmills[item.y])
	return {"x": at.x, "y": at.y}


# A windmill's fields: its pin, blades, then speed (driven) or friction (free).
static func _windmill_values(spec: WindmillSpec) -> Dictionary:
	var values := {
		"x": spec.position.x,
		"y": spec.position.y,
		"blades": float(spec.blades),
		"length": spec.length,
		"free": 1.0 if spec.free_spin else 0.0,
	}
	if spec.free_spin:
		values["friction"] = spec.friction
	else:
		values["speed"] = spec.speed
	return values


# A bonus pocket's fields: the cup's, then its role's own.
static func _bonus_values(spec: BonusPocketSpec) -> Dictionary:
	var values := {
		"x": spec.position.x,
		"y": spec.position.y,
		"width": spec.width,
		"depth": spec.depth,
		"payout": float(spec.payout),
	}
	if spec.role == BonusPocketSpec.Role.START:
		values["symbols"] = float(spec.symbols)
	elif spec.role == BonusPocketSpec.Role.ATTACKER:
		values["open_seconds"] = spec.open_seconds
		values["open_catches"] = float(spec.open_catches)
	return values


## The action that sets field `key` of `item` to `value`, or null when nothing changes.
static func action_for(level: BoardLevel, item: Vector2i, key: String, value: float) -> BoardAction:
	var now := values_of(level, item)
	var current: float = now.get(key, NAN)
	if not now.has(key) or is_equal_approx(current, value):
		return null
	var at := Items.position_of(level, item)
	var target := Vector2(value, at.y) if key == "x" else Vector2(at.x, value)
	match item.x:
		Items.Kind.POCKET:
			if key in ["x", "y"]:
				return MoveItemsAction.new(level, [item] as Array[Vector2i], target - at)
			var spec: PocketSpec = level.pockets[item.y]
			var width := value if key == "width" else spec.width
			var depth := value if key == "depth" else spec.depth
			var payout := int(value) if key == "payout" else spec.payout
			return EditPocketAction.new(level, item.y, width, depth, payout)
		Items.Kind.WALL:
			var end := item.y * 2 + (1 if key.begins_with("b") else 0)
			var point := level.walls[end]
			point = Vector2(value, point.y) if key.ends_with("x") else Vector2(point.x, value)
			return SetPointAction.new(level, "walls", end, point, "Set wall end")
		Items.Kind.BONUS:
			if key in ["x", "y"]:
				return MoveItemsAction.new(level, [item] as Array[Vector2i], target - at)
			return BonusActions.EditBonus.new(level, item.y, key, value)
		Items.Kind.WINDMILL:
			if key in ["x", "y"]:
				return MoveItemsAction.new(level, [item] as Array[Vector2i], target - at)
			return EditWindmillAction.new(level, item.y, key, value)
		Items.Kind.GOAL:
			if key == "radius":
				return SetPropertiesAction.new(level, {"goal_radius": value}, "Set goal radius")
			return SetPropertiesAction.new(level, {"goal_center": target}, "Set goal position")
	var field: String = POINT_FIELD[item.x]
	return SetPointAction.new(level, field, item.y, target, "Set %s position" % _noun(item))


## The action that sets x or y of `item` in mirror mode (axis x `axis`): its mirror twin
## moves with it, as a drag moves both; null when the item has no twin (then `action_for`).
static func mirrored_action_for(
	level: BoardLevel, item: Vector2i, key: String, value: float, axis: float
) -> BoardAction:
	if not key in ["x", "y"] or item.x in [Items.Kind.GOAL, Items.Kind.WALL]:
		return null
	if not Items.is_valid(level, item):
		return null
	var twin := Mirror.partner(level, item, axis)
	if twin == Items.NONE or twin == item:
		return null
	var at := Items.position_of(level, item)
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
		var twin := Items.NONE if is_nan(axis) else Mirror.partner(level, item, axis)
		var moves_twin := key in ["x", "y"] and twin != Items.NONE
		if moves_twin and targets.has(twin):
			continue  # its partner's edit moves it
		targets.append(item)
		if not key in ["x", "y"] and twin != Items.NONE and not targets.has(twin):
			targets.append(twin)
	return targets


## A short name for the item's kind ("pin", "ball start").
static func _noun(item: Vector2i) -> String:
	var nouns: Array[String] = [
		"pin", "pocket", "wall", "black hole", "ball start", "goal", "bonus pocket", "windmill"
	]
	return nouns[item.x]
