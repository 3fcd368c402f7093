@tool
extends RefCounted
## The stable name of a selectable item: its ItemIds list and id ("goal" for the goal). An
## index moves when an item before it is deleted or an undo brings one back; the key does
## not, so the editor's selection keeps pointing at the same things (BoardEditSession).

const Items := preload("res://addons/board_editor/core/board_items.gd")
const GOAL_LIST := "goal"
## The ItemIds list of each kind of item (bonus pockets: the list of their role).
const LIST_OF_KIND := {
	Items.Kind.PIN: "pins",
	Items.Kind.POCKET: "pockets",
	Items.Kind.WALL: "walls",
	Items.Kind.HOLE: "holes",
	Items.Kind.START: "ball_starts",
}


## The key of `item`: [list, id], or [] for an item that is not on the board.
static func of(level: BoardLevel, item: Vector2i) -> Array:
	if not Items.is_valid(level, item):
		return []
	if item.x == Items.Kind.GOAL:
		return [GOAL_LIST, item.y]
	if item.x == Items.Kind.BONUS:
		var spec := level.bonus_pockets[item.y]
		return [ItemIds.BONUS_LISTS[spec.role], ItemIds.of_bonus(level, item.y)]
	var list: String = LIST_OF_KIND[item.x]
	return [list, ItemIds.of(level, list, item.y)]


## The items `keys` name on `level` now, in the keys' order and each once; the keys of
## items that are gone are left out.
static func find_all(level: BoardLevel, keys: Array) -> Array[Vector2i]:
	var index_by_id := {}
	var found: Array[Vector2i] = []
	var seen := {}
	for key: Array in keys:
		var item := _find(level, key, index_by_id)
		if item != Items.NONE and not seen.has(item):
			seen[item] = true
			found.append(item)
	return found


# `index_by_id` keeps each list's id → index table, built once per call of find_all.
static func _find(level: BoardLevel, key: Array, index_by_id: Dictionary) -> Vector2i:
	var list: String = key[0]
	if list == GOAL_LIST:
		var goal_index: int = key[1]
		var goal := Items.make(Items.Kind.GOAL, goal_index)
		return goal if Items.is_valid(level, goal) else Items.NONE
	if not index_by_id.has(list):
		index_by_id[list] = _index_table(level, list)
	var table: Dictionary = index_by_id[list]
	var index: int = table.get(key[1], -1)
	if index < 0:
		return Items.NONE
	var kind: int = (
		Items.Kind.BONUS if ItemIds.BONUS_LISTS.has(list) else LIST_OF_KIND.find_key(list)
	)
	return Items.make(kind, index)


# id → index of the items of `list` (for a bonus list: the index in level.bonus_pockets).
static func _index_table(level: BoardLevel, list: String) -> Dictionary:
	var table := {}
	var role := ItemIds.BONUS_LISTS.find(list)
	if role < 0:
		for i in ItemIds.count(level, list):
			table[ItemIds.of(level, list, i)] = i
		return table
	var place := 0
	for i in level.bonus_pockets.size():
		var spec := level.bonus_pockets[i]
		if spec != null and spec.role == role:
			table[ItemIds.of(level, list, place)] = i
			place += 1
	return table
