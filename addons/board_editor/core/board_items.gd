@tool
extends RefCounted
## What the editor can select on a board, and how to read one item back.
##
## An item is a `Vector2i(kind, index)`: pins, pockets, walls (pair index), holes, ball
## starts, the goal, bonus pockets (index into `bonus_pockets`) and windmills. Pins that belong to a
## pocket are never items of their own: the pocket is (its rim pins are stamped, not placed
## one by one); a bonus pocket's pins are not on the board at all (the world stamps them).

enum Kind { PIN, POCKET, WALL, HOLE, START, GOAL, BONUS, WINDMILL }

## Returned by the pickers when nothing is there.
const NONE := Vector2i(-1, -1)
## The BoardLevel fields that hold items (what adding or deleting items may change).
const ITEM_FIELDS: Array[String] = [
	"pins",
	"pin_pocket",
	"pin_special",
	"pockets",
	"walls",
	"holes",
	"ball_starts",
	"bonus_pockets",
	"windmills",
]

## The BoardLevel fields that hold where items stand (what moving, flipping or arranging
## items may change).
const POSITION_FIELDS: Array[String] = [
	"pins",
	"pockets",
	"walls",
	"holes",
	"ball_starts",
	"goal_center",
	"bonus_pockets",
	"windmills",
]


## The item of `kind` at `index`.
static func make(kind: Kind, index: int) -> Vector2i:
	return Vector2i(kind, index)


## How many walls `points` holds: each wall is two points in a row; a lone last point is
## not a wall.
static func wall_count(points: PackedVector2Array) -> int:
	@warning_ignore("integer_division")  # whole walls only
	return points.size() / 2


## The point that represents an item: a centre, a pocket's mouth, a wall's midpoint.
static func position_of(level: BoardLevel, item: Vector2i) -> Vector2:
	match item.x:
		Kind.PIN:
			return level.pins[item.y]
		Kind.POCKET:
			return level.pockets[item.y].position
		Kind.WALL:
			return (level.walls[item.y * 2] + level.walls[item.y * 2 + 1]) * 0.5
		Kind.HOLE:
			return level.holes[item.y]
		Kind.START:
			return level.ball_starts[item.y]
		Kind.BONUS:
			return level.bonus_pockets[item.y].position
		Kind.WINDMILL:
			return level.windmills[item.y].position
		_:
			return level.goal_center


## True when the item still exists on the board (indices go stale after an undo).
static func is_valid(level: BoardLevel, item: Vector2i) -> bool:
	if item.y < 0:
		return false
	match item.x:
		Kind.PIN:
			return item.y < level.pins.size()
		Kind.POCKET:
			return item.y < level.pockets.size()
		Kind.WALL:
			return item.y < wall_count(level.walls)
		Kind.HOLE:
			return item.y < level.holes.size()
		Kind.START:
			return item.y < level.ball_starts.size()
		Kind.GOAL:
			return level.is_maze()
		Kind.BONUS:
			return item.y < level.bonus_pockets.size() and level.bonus_pockets[item.y] != null
		Kind.WINDMILL:
			return item.y < level.windmills.size() and level.windmills[item.y] != null
	return false


## Indices of the items of one kind in a selection, sorted and without repeats.
static func indices_of(items: Array[Vector2i], kind: Kind) -> PackedInt32Array:
	var found := PackedInt32Array()
	for item in items:
		if item.x == kind and not found.has(item.y):
			found.append(item.y)
	found.sort()
	return found


## The pin indices that make up pocket `pocket_index` (its rim and special pin).
static func pocket_pins(level: BoardLevel, pocket_index: int) -> PackedInt32Array:
	var found := PackedInt32Array()
	for i in level.pin_pocket.size():
		if level.pin_pocket[i] == pocket_index:
			found.append(i)
	return found


## A copy of the selected items as plain data, positions relative to `origin`, for the
## clipboard and for duplicating: {pins, walls, holes, starts, pockets, bonus, windmills}.
static func extract(level: BoardLevel, items: Array[Vector2i], origin: Vector2) -> Dictionary:
	# Local arrays, stored at the end: a packed array taken out of a Dictionary is a copy.
	var pins := PackedVector2Array()
	var walls := PackedVector2Array()
	var holes := PackedVector2Array()
	var starts := PackedVector2Array()
	var pockets: Array = []
	var bonus: Array = []
	var windmills: Array = []
	for item in items:
		if not is_valid(level, item):
			continue
		match item.x:
			Kind.PIN:
				pins.append(level.pins[item.y] - origin)
			Kind.WALL:
				walls.append(level.walls[item.y * 2] - origin)
				walls.append(level.walls[item.y * 2 + 1] - origin)
			Kind.HOLE:
				holes.append(level.holes[item.y] - origin)
			Kind.START:
				starts.append(level.ball_starts[item.y] - origin)
			Kind.POCKET:
				var spec: PocketSpec = level.pockets[item.y]
				pockets.append(
					PocketSpec.create(spec.position - origin, spec.width, spec.depth, spec.payout)
				)
			Kind.BONUS:
				bonus.append(moved_bonus(level.bonus_pockets[item.y], -origin))
			Kind.WINDMILL:
				windmills.append(level.windmills[item.y].moved(-origin))
	return {
		"pins": pins,
		"walls": walls,
		"holes": holes,
		"starts": starts,
		"pockets": pockets,
		"bonus": bonus,
		"windmills": windmills,
	}


## A copy of bonus pocket `spec` (every field) moved by `offset`.
static func moved_bonus(spec: BonusPocketSpec, offset: Vector2) -> BonusPocketSpec:
	var copy := spec.duplicate() as BonusPocketSpec
	copy.position = spec.position + offset
	return copy


## An empty item set: the shape `extract()` returns and the add action takes.
static func empty_set() -> Dictionary:
	return {
		"pins": PackedVector2Array(),
		"walls": PackedVector2Array(),
		"holes": PackedVector2Array(),
		"starts": PackedVector2Array(),
		"pockets": [],
		"bonus": [],
		"windmills": [],
	}


## The same item set moved by `offset` (pocket specs are copied, never shared).
static func offset_set(data: Dictionary, offset: Vector2) -> Dictionary:
	var moved := empty_set()
	for key: String in ["pins", "walls", "holes", "starts"]:
		var source: PackedVector2Array = data.get(key, PackedVector2Array())
		var target: PackedVector2Array = moved[key]
		for point in source:
			target.append(point + offset)
	var moved_pockets: Array = moved["pockets"]
	for spec: PocketSpec in data.get("pockets", []):
		moved_pockets.append(
			PocketSpec.create(spec.position + offset, spec.width, spec.depth, spec.payout)
		)
	var moved_bonus_pockets: Array = moved["bonus"]
	for spec: BonusPocketSpec in data.get("bonus", []):
		moved_bonus_pockets.append(moved_bonus(spec, offset))
	var moved_windmills: Array = moved["windmills"]
	for spec: WindmillSpec in data.get("windmills", []):
		moved_windmills.append(spec.moved(offset))
	return moved


## How many things an item set holds.
static func set_size(data: Dictionary) -> int:
	var walls: PackedVector2Array = data.get("walls", PackedVector2Array())
	var total := wall_count(walls)
	for key: String in ["pins", "holes", "starts"]:
		var points: PackedVector2Array = data.get(key, PackedVector2Array())
		total += points.size()
	var pockets: Array = data.get("pockets", [])
	var bonus: Array = data.get("bonus", [])
	var windmills: Array = data.get("windmills", [])
	return total + pockets.size() + bonus.size() + windmills.size()
