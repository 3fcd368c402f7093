@tool
extends RefCounted
## What the property panel shows and edits for a selection of one item: exact x / y for
## pins, holes, starts and the goal; a pocket's mouth, width, depth and payout; a wall's two
## ends; the goal's radius; a bonus pocket's mouth, size and payout, and per role its reel
## symbols (start pocket) or how long and for how many catches it opens (attacker); a
## windmill's pin, blades, length, and its speed (driven) or friction (free). Each field
## edit becomes one action (one undo step).

const Items := preload("res://addons/board_editor/core/board_items.gd")
const MoveItemsAction := preload("res://addons/board_editor/actions/move_items_action.gd")
const SetPointAction := preload("res://addons/board_editor/actions/set_point_action.gd")
const EditPocketAction := preload("res://addons/board_editor/actions/edit_pocket_action.gd")
const SetPropertiesAction := preload("res://addons/board_editor/actions/set_properties_action.gd")
const BonusActions := preload("res://addons/board_editor/bonus/bonus_actions.gd")
const Mirror := preload("res://addons/board_editor/core/mirror.gd")
const EditWindmillAction := preload("res://addons/board_editor/actions/edit_windmill_action.gd")

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


## A short name for the item's kind ("pin", "ball start").
static func _noun(item: Vector2i) -> String:
	var nouns: Array[String] = [
		"pin", "pocket", "wall", "black hole", "ball start", "goal", "bonus pocket", "windmill"
	]
	return nouns[item.x]
