@tool
extends BoardAction
## Removes items: pins, pockets (with their rim pins; the other pins' pocket indices are
## renumbered), walls, holes, ball starts, bonus pockets and windmills. The goal cannot be removed,
## only moved.

const Items := preload("res://addons/board_editor/core/board_items.gd")

var _items: Array[Vector2i]


func _init(on_level: BoardLevel, items: Array[Vector2i]) -> void:
	super(on_level)
	_items = items.duplicate()


func get_name() -> String:
	return "Delete %d board item%s" % [_items.size(), "" if _items.size() == 1 else "s"]


func _touched_fields() -> PackedStringArray:
	return PackedStringArray(Items.ITEM_FIELDS)


func _apply() -> void:
	var gone_pockets := Items.indices_of(_items, Items.Kind.POCKET)
	var gone_pins := Items.indices_of(_items, Items.Kind.PIN)
	# Pocket index before -> after, -1 for a removed pocket.
	var renumber := PackedInt32Array()
	var pockets: Array[PocketSpec] = []
	for i in level.pockets.size():
		if gone_pockets.has(i):
			renumber.append(-1)
		else:
			renumber.append(pockets.size())
			pockets.append(level.pockets[i])
	var pins := PackedVector2Array()
	var pin_pocket := PackedInt32Array()
	var pin_special := PackedByteArray()
	for i in level.pins.size():
		var owner := level.pin_pocket[i] if i < level.pin_pocket.size() else -1
		if gone_pins.has(i) or (owner >= 0 and owner < renumber.size() and renumber[owner] < 0):
			continue
		pins.append(level.pins[i])
		pin_pocket.append(renumber[owner] if owner >= 0 and owner < renumber.size() else -1)
		pin_special.append(level.pin_special[i] if i < level.pin_special.size() else 0)
	level.pockets = pockets
	level.pins = pins
	level.pin_pocket = pin_pocket
	level.pin_special = pin_special
	var walls := PackedVector2Array()
	var gone_walls := Items.indices_of(_items, Items.Kind.WALL)
	for w in Items.wall_count(level.walls):
		if not gone_walls.has(w):
			walls.append(level.walls[w * 2])
			walls.append(level.walls[w * 2 + 1])
	level.walls = walls
	level.holes = _without(level.holes, Items.indices_of(_items, Items.Kind.HOLE))
	level.ball_starts = _without(level.ball_starts, Items.indices_of(_items, Items.Kind.START))
	var gone_bonus := Items.indices_of(_items, Items.Kind.BONUS)
	if not gone_bonus.is_empty():
		var bonus: Array[BonusPocketSpec] = []
		for i in level.bonus_pockets.size():
			if not gone_bonus.has(i):
				bonus.append(level.bonus_pockets[i])
		level.bonus_pockets = bonus
	var gone_windmills := Items.indices_of(_items, Items.Kind.WINDMILL)
	if not gone_windmills.is_empty():
		var wheels: Array[WindmillSpec] = []
		for i in level.windmills.size():
			if not gone_windmills.has(i):
				wheels.append(level.windmills[i])
		level.windmills = wheels


static func _without(points: PackedVector2Array, gone: PackedInt32Array) -> PackedVector2Array:
	var kept := PackedVector2Array()
	for i in points.size():
		if not gone.has(i):
			kept.append(points[i])
	return kept
