@tool
class_name ItemKinds
extends RefCounted
## Every kind of board item, declared once: one file per kind in this folder builds its
## ItemKind row, and ROWS lists the files in table order: the order of the item lines in
## a board file (pachinko's, then the maze's; the goal, a field, last) and of the id
## counters. The item ids, the
## editor's selection, names, undo snapshots, moves, mirroring, adding and deleting go by
## this table instead of switching on the kind (tests/unit/test_item_kinds_round_trip.gd
## walks every row through file, level and editor).
##
## A new kind is one new file here plus its row in ROWS (and its BoardLevel fields).

## The kind files, in table order.
const ROWS: Array[GDScript] = [
	preload("res://scripts/board/item_kinds/pin_kind.gd"),
	preload("res://scripts/board/item_kinds/pocket_kind.gd"),
	preload("res://scripts/board/item_kinds/start_pocket_kind.gd"),
	preload("res://scripts/board/item_kinds/attacker_kind.gd"),
	preload("res://scripts/board/item_kinds/tulip_kind.gd"),
	preload("res://scripts/board/item_kinds/windmill_kind.gd"),
	preload("res://scripts/board/item_kinds/wall_kind.gd"),
	preload("res://scripts/board/item_kinds/ball_start_kind.gd"),
	preload("res://scripts/board/item_kinds/hole_kind.gd"),
	preload("res://scripts/board/item_kinds/goal_kind.gd"),
	preload("res://scripts/board/item_kinds/floor_arrow_kind.gd"),
]

# The rows, built once as the class loads (the scripts are @tool, so the editor builds
# them too). Rows are shared: nobody writes to them after this.
static var _rows: Array[ItemKind] = _build()
static var _by_list: Dictionary[String, ItemKind] = _index_by_list()


## Every row, in table order.
static func all() -> Array[ItemKind]:
	return _rows


## The rows whose items have stable ids (every kind but the goal), in table order: the
## lists of ItemIds.
static func listed() -> Array[ItemKind]:
	return _rows.filter(func(kind: ItemKind) -> bool: return kind.has_ids())


## The rows of `game` (BoardLevel.Kind) with an item line in board files, in table order.
static func of_game(game: BoardLevel.Kind) -> Array[ItemKind]:
	return _rows.filter(
		func(kind: ItemKind) -> bool: return kind.game == game and not kind.file_fields.is_empty()
	)


## The row of list `list` ("pins", "tulips", "goal"), or null.
static func of_list(list: String) -> ItemKind:
	return _by_list.get(list, null)


## The row whose board file line is keyed `key` ("pin", "tulip"), or null.
static func of_name(key: String) -> ItemKind:
	for kind in _rows:
		if kind.name == key:
			return kind
	return null


## The first row of the editor's `pick` (ItemKind.Pick): for BONUS, the start pockets,
## which handle `bonus_pockets` as a whole (`remove`, the item set) like their role-mates.
static func of_pick(pick: int) -> ItemKind:
	for kind in _rows:
		if kind.pick == pick:
			return kind
	return null


## The row of the bonus pockets of `role` (BonusPocketSpec.Role).
static func of_role(role: int) -> ItemKind:
	for kind in _rows:
		if kind.shape == ItemKind.Shape.ROLE_SPEC and kind.role == role:
			return kind
	return null


## The row of the editor's item `Vector2i(pick, index)` on `level` (a bonus pocket: its
## role's), or null when there is no such item.
static func of_item(level: BoardLevel, item: Vector2i) -> ItemKind:
	var kind := of_pick(item.x)
	if kind == null or kind.shape != ItemKind.Shape.ROLE_SPEC:
		return kind
	if item.y < 0 or item.y >= level.bonus_pockets.size() or level.bonus_pockets[item.y] == null:
		return null
	return of_role(level.bonus_pockets[item.y].role)


## The row whose items live in BoardLevel field `field` (the first, for `bonus_pockets`),
## or null.
static func of_field(field: String) -> ItemKind:
	for kind in _rows:
		if kind.field == field:
			return kind
	return null


## Every item of `level` as the editor names it, `Vector2i(pick, index)`, in table order
## (the bonus pockets in board order, which is role order), skipped entries included.
static func items_of(level: BoardLevel) -> Array[Vector2i]:
	var items: Array[Vector2i] = []
	for kind in _rows:
		for index in kind.field_indices(level):
			if kind.is_valid(level, index):
				items.append(Vector2i(kind.pick, index))
	return items


## The editor's layers of `game` (BoardLevel.Kind), in table order, each once: layer name
## -> the BoardPainter.Layer key that draws it ("PINS").
static func layers_of(game: BoardLevel.Kind) -> Dictionary[String, String]:
	var found: Dictionary[String, String] = {}
	for kind in _rows:
		if kind.game == game and not kind.layer.is_empty() and not found.has(kind.layer):
			found[kind.layer] = kind.paint_layer
	return found


## The first row of each item-set key (BoardItems.extract), in table order.
static func set_rows() -> Array[ItemKind]:
	var seen := {}
	var found: Array[ItemKind] = []
	for kind in _rows:
		if not kind.set_key.is_empty() and not seen.has(kind.set_key):
			seen[kind.set_key] = true
			found.append(kind)
	return found


## The one row for each editor pick, in table order (a bonus pick's rows share a field).
static func pick_rows() -> Array[ItemKind]:
	var seen := {}
	var found: Array[ItemKind] = []
	for kind in _rows:
		if not seen.has(kind.pick):
			seen[kind.pick] = true
			found.append(kind)
	return found


## Every BoardLevel field that adding or deleting items may change, each once.
static func item_fields() -> PackedStringArray:
	return _union(func(kind: ItemKind) -> PackedStringArray: return kind.item_fields)


## Every BoardLevel field that moving or mirroring items may change, each once.
static func position_fields() -> PackedStringArray:
	return _union(func(kind: ItemKind) -> PackedStringArray: return kind.position_fields)


static func _union(fields_of: Callable) -> PackedStringArray:
	var fields := PackedStringArray()
	for kind in _rows:
		var of_kind: PackedStringArray = fields_of.call(kind)
		for field in of_kind:
			if not fields.has(field):
				fields.append(field)
	return fields


static func _build() -> Array[ItemKind]:
	var rows: Array[ItemKind] = []
	var next_pick: int = ItemKind.Pick.values().max() + 1
	for script in ROWS:
		var kind: ItemKind = script.call("row")
		if kind.pick < 0:
			kind.pick = next_pick
			next_pick += 1
		rows.append(kind)
	return rows


static func _index_by_list() -> Dictionary[String, ItemKind]:
	var table: Dictionary[String, ItemKind] = {}
	for kind in _rows:
		table[kind.list] = kind
	return table
