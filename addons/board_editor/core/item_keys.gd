@tool
extends RefCounted
## The stable name of a selectable item: its ItemIds list and id ("goal" for the goal). An
## index moves when an item before it is deleted or an undo brings one back; the key does
## not, so the editor's selection keeps pointing at the same things (BoardEditSession).
## The list of an item is its ItemKinds row's; an item without ids (the goal) is keyed by
## its index.

const BoardItems := preload("res://addons/board_editor/core/board_items.gd")


## The key of `item`: [list, id], or [] for an item that is not on the board.
static func of(level: BoardLevel, item: Vector2i) -> Array:
	if not BoardItems.is_valid(level, item):
		return []
	var kind := ItemKinds.of_item(level, item)
	if not kind.has_ids():
		return [kind.list, item.y]
	if kind.shape == ItemKind.Shape.ROLE_SPEC:
		return [kind.list, ItemIds.of_bonus(level, item.y)]
	return [kind.list, ItemIds.of(level, kind.list, item.y)]


## The items `keys` name on `level` now, in the keys' order and each once; the keys of
## items that are gone are left out.
static func find_all(level: BoardLevel, keys: Array) -> Array[Vector2i]:
	var index_by_id := {}
	var found: Array[Vector2i] = []
	var seen := {}
	for key: Array in keys:
		var item := _find(level, key, index_by_id)
		if item != BoardItems.NONE and not seen.has(item):
			seen[item] = true
			found.append(item)
	return found


# `index_by_id` keeps each list's id → index table, built once per call of find_all.
static func _find(level: BoardLevel, key: Array, index_by_id: Dictionary) -> Vector2i:
	var list: String = key[0]
	var kind := ItemKinds.of_list(list)
	if kind == null:
		return BoardItems.NONE
	if not kind.has_ids():
		var at: int = key[1]
		var item := BoardItems.make(kind.pick, at)
		return item if BoardItems.is_valid(level, item) else BoardItems.NONE
	if not index_by_id.has(list):
		index_by_id[list] = _index_table(level, kind)
	var table: Dictionary = index_by_id[list]
	var index: int = table.get(key[1], -1)
	if index < 0:
		return BoardItems.NONE
	return BoardItems.make(kind.pick, index)


# id → index of the items of `kind` (for a bonus role: the index in level.bonus_pockets).
static func _index_table(level: BoardLevel, kind: ItemKind) -> Dictionary:
	var table := {}
	var indices := kind.field_indices(level)
	for place in indices.size():
		table[ItemIds.of(level, kind.list, place)] = indices[place]
	return table
