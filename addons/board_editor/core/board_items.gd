@tool
extends RefCounted
## What the editor can select on a board, and how to read one item back.
##
## An item is a `Vector2i(kind, index)`: pins, pockets, walls (pair index), holes, ball
## starts, the goal, bonus pockets (index into `bonus_pockets`) and windmills. Pins that belong to a
## pocket are never items of their own: the pocket is (its rim pins are stamped, not placed
## one by one); a bonus pocket's pins are not on the board at all (the world stamps them).

## What an item's `kind` is: the table's picks (ItemKind.Pick), one per selectable field.
## Named like the enum it stands for, so `Items.Kind.PIN` reads as it always has.
# gdlint: ignore=constant-name
const Kind := ItemKind.Pick

## Returned by the pickers when nothing is there.
const NONE := Vector2i(-1, -1)


## The BoardLevel fields that hold items (what adding or deleting items may change).
static func item_fields() -> PackedStringArray:
	return ItemKinds.item_fields()


## The BoardLevel fields that hold where items stand (what moving, flipping or arranging
## items may change).
static func position_fields() -> PackedStringArray:
	return ItemKinds.position_fields()


## The item of `kind` at `index`.
static func make(kind: int, index: int) -> Vector2i:
	return Vector2i(kind, index)


## How many walls `points` holds: each wall is two points in a row; a lone last point is
## not a wall.
static func wall_count(points: PackedVector2Array) -> int:
	@warning_ignore("integer_division")  # whole walls only
	return points.size() / 2


## The point that represents an item: a centre, a pocket's mouth, a wall's midpoint.
static func position_of(level: BoardLevel, item: Vector2i) -> Vector2:
	var kind := ItemKinds.of_item(level, item)
	return kind.position_of(level, item.y) if kind != null else Vector2.ZERO


## True when the item still exists on the board (indices go stale after an undo).
static func is_valid(level: BoardLevel, item: Vector2i) -> bool:
	var kind := ItemKinds.of_item(level, item)
	return kind != null and kind.is_valid(level, item.y)


## Indices of the items of one kind in a selection, sorted and without repeats.
static func indices_of(items: Array[Vector2i], kind: int) -> PackedInt32Array:
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
## clipboard and for duplicating: {pins, walls, holes, starts, pockets, bonus, windmills}
## (each kind's ItemKind.set_key).
static func extract(level: BoardLevel, items: Array[Vector2i], origin: Vector2) -> Dictionary:
	# Plain arrays first, packed at the end: a packed array taken out of a Dictionary is a
	# copy, so appending to one item by item would copy it each time.
	var collected := {}
	for item in items:
		var kind := ItemKinds.of_item(level, item)
		if kind == null or kind.set_key.is_empty() or not kind.is_valid(level, item.y):
			continue
		var values: Array = collected.get_or_add(kind.set_key, [])
		values.append_array(kind.values_of(level, item.y, origin))
	var data := empty_set()
	for kind in ItemKinds.set_rows():
		if collected.has(kind.set_key):
			var values: Array = collected[kind.set_key]
			data[kind.set_key] = set_entry(kind, values)
	return data


## A copy of bonus pocket `spec` (every field) moved by `offset`.
static func moved_bonus(spec: BonusPocketSpec, offset: Vector2) -> BonusPocketSpec:
	var copy := spec.duplicate() as BonusPocketSpec
	copy.position = spec.position + offset
	return copy


## An empty item set: the shape `extract()` returns and the add action takes (points and
## wall ends as PackedVector2Array, resources as Array).
static func empty_set() -> Dictionary:
	var data := {}
	for kind in ItemKinds.set_rows():
		data[kind.set_key] = set_entry(kind, [])
	return data


## The same item set moved by `offset` (resources are copied, never shared).
static func offset_set(data: Dictionary, offset: Vector2) -> Dictionary:
	var moved := empty_set()
	for kind in ItemKinds.set_rows():
		var values: Array = []
		for value: Variant in set_values(data, kind):
			values.append(kind.moved_value(value, offset))
		moved[kind.set_key] = set_entry(kind, values)
	return moved


## How many things an item set holds (a wall is two points).
static func set_size(data: Dictionary) -> int:
	var total := 0
	for kind in ItemKinds.set_rows():
		var values := set_values(data, kind)
		@warning_ignore("integer_division")  # whole walls only
		var walls := values.size() / 2
		total += walls if kind.shape == ItemKind.Shape.SEGMENT else values.size()
	return total


## The values a set holds for `kind` (its `set_key`) as a plain Array: points, walls' ends
## in pairs, resources.
static func set_values(data: Dictionary, kind: ItemKind) -> Array:
	var held: Variant = data.get(kind.set_key, [])
	if held is PackedVector2Array:
		var points: PackedVector2Array = held
		return Array(points)
	var values: Array = held
	return values


## `values` as an item set holds them for `kind`: points and walls' ends packed
## (PackedVector2Array), resources in an Array.
static func set_entry(kind: ItemKind, values: Array) -> Variant:
	if kind.shape == ItemKind.Shape.POINT or kind.shape == ItemKind.Shape.SEGMENT:
		return PackedVector2Array(values)
	return values
