class_name ItemIds
extends RefCounted
## Stable item ids: every pin, pocket, windmill, wall, black hole and ball start has a number
## that stays its own when a neighbour is deleted or added, so a problem message ("Pins 143 and 459
## overlap") still names the same two pins after an edit. Ids are per list, 1 and up, kept in
## BoardLevel's `*_ids` arrays beside the items and written in the board file (`"id": 17`).
## A board made in code, or a file without ids, numbers its items 1, 2, 3... in order.
## A pocket's rim pins are not items of their own: the pocket stamps them (PocketStamp) and
## the board file does not store them, so their id is 0 and messages name them by their
## pocket (`pin_label`).
## The bonus pockets (BoardLevel.bonus_pockets) are three lists by role, each with its own
## ids ("Tulip 2", "Attacker 1"), as the board file stores them (`start_pocket`, `attacker`,
## `tulip` lines).
## New ids come from the board's per-list counter (BoardLevel.next_ids), which never goes
## back: deleting the item with the highest id, or undoing an add, does not free its id.
## The lists, their fields and what identifies an item across an edit come from ItemKinds.

## The largest id a file may use.
const MAX_ID := ItemKind.MAX_ID


## The item lists that have ids, in ItemKinds order (the order counters are written in):
## "pins", "pockets", ... "windmills".
static func lists() -> Array[String]:
	var names: Array[String] = []
	for kind in ItemKinds.listed():
		names.append(kind.list)
	return names


## The BoardLevel field holding the ids of `list` ("pin_ids").
static func id_field_of(list: String) -> String:
	return ItemKinds.of_list(list).id_field


## How many items `list` holds (a pocket's rim pins counted among the pins).
static func count(level: BoardLevel, list: String) -> int:
	return ItemKinds.of_list(list).count(level)


## The id of item `index` of `list` (its place, 1-based, if the board has no id for it);
## 0 for a pocket's rim pin, which has none.
static func of(level: BoardLevel, list: String, index: int) -> int:
	var kind := ItemKinds.of_list(list)
	if kind.skips.is_valid() and kind.skips.call(level, index):
		return 0
	var ids := ids_of(level, list)
	return ids[index] if index < ids.size() and ids[index] > 0 else index + 1


## The board field that holds the items of `list` ("bonus_pockets" for the bonus lists).
static func field_of(list: String) -> String:
	return ItemKinds.of_list(list).field


## True when pin `index` belongs to a pocket (stamped from it, never stored on its own).
static func is_rim_pin(level: BoardLevel, index: int) -> bool:
	return PinKind.is_rim_pin(level, index)


## How a message names pin `index`: "pin 17", or "a pin of pocket 2's rim" for a pin the
## pocket stamps (those have no id of their own). Starts lower case; a message capitalises.
static func pin_label(level: BoardLevel, index: int) -> String:
	if is_rim_pin(level, index):
		var pocket := level.pin_pocket[index]
		var pocket_id := (
			of(level, "pockets", pocket) if pocket < level.pockets.size() else pocket + 1
		)
		return "a pin of pocket %d's rim" % pocket_id
	return "pin %d" % of(level, "pins", index)


## The id of bonus pocket `index` of `level.bonus_pockets` (unique among its role).
static func of_bonus(level: BoardLevel, index: int) -> int:
	var spec := level.bonus_pockets[index]
	var list := ItemKinds.of_role(spec.role).list
	var place := 0
	for k in index:
		var other := level.bonus_pockets[k]
		if other != null and other.role == spec.role:
			place += 1
	return of(level, list, place)


## The index in `level.bonus_pockets` of the bonus pocket of `list` with id `id`, or -1.
static func bonus_index(level: BoardLevel, list: String, id: int) -> int:
	var place := index_of(level, list, id)
	var indices := ItemKinds.of_list(list).field_indices(level)
	return indices[place] if place >= 0 and place < indices.size() else -1


## The index of the item of `list` with id `id`, or -1.
static func index_of(level: BoardLevel, list: String, id: int) -> int:
	for i in count(level, list):
		if of(level, list, i) == id:
			return i
	return -1


## The stored ids of `list` (may be shorter than the list; see `of`).
static func ids_of(level: BoardLevel, list: String) -> PackedInt32Array:
	var ids: PackedInt32Array = level.get(id_field_of(list))
	return ids


## The id the next new item of `list` gets: the board's counter, and never one an item of
## the list already has (a hand-edited file may hold a counter lower than its ids).
static func next_id(level: BoardLevel, list: String) -> int:
	var largest := 0
	for i in count(level, list):
		largest = maxi(largest, of(level, list, i))
	return maxi(_counter(level, list), largest + 1)


## Makes every id array match its list: missing, zero or repeated ids get fresh numbers.
static func fill(level: BoardLevel) -> void:
	for kind in ItemKinds.listed():
		var list := kind.list
		var ids := ids_of(level, list).duplicate()
		var total := count(level, list)
		ids.resize(total)
		var seen := {}
		var fresh := maxi(_largest(ids) + 1, _counter(level, list))
		var changed := false
		for i in total:
			if kind.skips.is_valid() and kind.skips.call(level, i):
				changed = changed or ids[i] != 0
				ids[i] = 0
				continue
			if ids[i] <= 0 or seen.has(ids[i]):
				ids[i] = fresh
				fresh += 1
				changed = true
			seen[ids[i]] = true
		if changed or ids.size() != ids_of(level, list).size():
			level.set(kind.id_field, ids)
		if changed:
			_advance(level, list, fresh)


## After an edit changed a list's length: items still at a position they had `before` (a
## BoardFieldCopy capture of the lists and their ids) keep their id, new ones get fresh ids
## from the board's counter, which moves past them.
## Pockets and bonus pockets keep theirs by object, so one re-stamped or moved is still itself.
## Pins are matched among the field pins only (rim pins have no id, and re-stamping a pocket
## moves its pins to the end of the list): the same number of field pins keeps their ids in
## order, so a moved pin stays itself.
static func reconcile(level: BoardLevel, before: Dictionary) -> void:
	for kind in ItemKinds.listed():
		var list := kind.list
		var id_field := kind.id_field
		var field := kind.field
		if not before.has(field) or not before.has(id_field):
			continue
		if kind.skips.is_valid():
			# Pins: the skipped entries (rim pins) have no id and move about when a pocket
			# is re-stamped, so the others are matched among themselves.
			_reconcile_pins(level, before)
			continue
		var old_ids: PackedInt32Array = before[id_field]
		var old_keys := kind.keys_of(before[field])
		var new_keys := kind.keys_of(level.get(field))
		if old_keys.size() == new_keys.size():
			continue  # moved or edited in place: every item is still itself
		# Items without a stored id had their place as id (see `of`).
		var had := PackedInt32Array()
		for i in old_keys.size():
			had.append(old_ids[i] if i < old_ids.size() and old_ids[i] > 0 else i + 1)
		var free := {}
		for i in old_keys.size():
			var waiting: Array = free.get_or_add(old_keys[i], [])
			waiting.append(had[i])
		var ids := PackedInt32Array()
		var fresh := maxi(_largest(had) + 1, _counter(level, list))
		for key: Variant in new_keys:
			var waiting: Array = free.get(key, [])
			if not waiting.is_empty():
				var kept: int = waiting.pop_front()
				ids.append(kept)
			else:
				ids.append(fresh)
				fresh += 1
		level.set(id_field, ids)
		_advance(level, list, fresh)


# `reconcile` for pins: field pins keep their ids (in order when their number is unchanged,
# else by position), rim pins get 0, new field pins fresh ids.
static func _reconcile_pins(level: BoardLevel, before: Dictionary) -> void:
	var old_pins: PackedVector2Array = before["pins"]
	var old_owner: PackedInt32Array = before.get("pin_pocket", level.pin_pocket)
	var old_ids: PackedInt32Array = before["pin_ids"]
	var had := PackedInt32Array()
	var had_at := PackedVector2Array()
	for i in old_pins.size():
		if i < old_owner.size() and old_owner[i] >= 0:
			continue
		had.append(old_ids[i] if i < old_ids.size() and old_ids[i] > 0 else i + 1)
		had_at.append(old_pins[i])
	var field := PackedInt32Array()
	for i in level.pins.size():
		if not is_rim_pin(level, i):
			field.append(i)
	var ids := PackedInt32Array()
	ids.resize(level.pins.size())
	var fresh := maxi(_largest(had) + 1, _counter(level, "pins"))
	if field.size() == had.size():
		for k in field.size():
			ids[field[k]] = had[k]
	else:
		var free := {}
		for k in had.size():
			var waiting: Array = free.get_or_add(had_at[k], [])
			waiting.append(had[k])
		for i in field:
			var waiting: Array = free.get(level.pins[i], [])
			if not waiting.is_empty():
				var kept: int = waiting.pop_front()
				ids[i] = kept
			else:
				ids[i] = fresh
				fresh += 1
	level.pin_ids = ids
	_advance(level, "pins", fresh)


## The counters a board file has to keep: list -> next id, only for lists whose counter is
## past their largest id + 1 (the top item was deleted); every other list's counter follows
## from its ids, so an unchanged board writes no counter line.
static func counters_to_save(level: BoardLevel) -> Dictionary[String, int]:
	var saved: Dictionary[String, int] = {}
	for list in lists():
		var largest := 0
		for i in count(level, list):
			largest = maxi(largest, of(level, list, i))
		var next := next_id(level, list)
		if next > largest + 1:
			saved[list] = next
	return saved


# The stored counter of `list` (1 when the board has none).
static func _counter(level: BoardLevel, list: String) -> int:
	var next: int = level.next_ids.get(list, 1)
	return next


# Moves the counter of `list` up to `next` (never down).
static func _advance(level: BoardLevel, list: String, next: int) -> void:
	if next <= _counter(level, list):
		return
	var counters := level.next_ids.duplicate()
	counters[list] = next
	level.next_ids = counters


static func _largest(ids: PackedInt32Array) -> int:
	var largest := 0
	for id in ids:
		largest = maxi(largest, id)
	return largest
