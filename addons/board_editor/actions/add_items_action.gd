@tool
extends BoardAction
## Adds a set of things to a board: field pins, pockets (with their stamped rim pins and
## special pin), walls, black holes, ball starts, bonus pockets (kept in role order, as
## the board file stores them) and windmills. Placing, pasting and duplicating are all this action;
## `added` lists the new items so the editor can select them.

const Items := preload("res://addons/board_editor/core/board_items.gd")
const PocketPins := preload("res://addons/board_editor/core/pocket_pins.gd")

## The new items after the last `do()`.
var added: Array[Vector2i] = []
var _data: Dictionary
var _name: String
var _pockets: Array[PocketSpec] = []
var _bonus: Array[BonusPocketSpec] = []
var _windmills: Array[WindmillSpec] = []


## `item_set` has the shape of BoardItems.empty_set(); positions are board pixels.
func _init(on_level: BoardLevel, item_set: Dictionary, action_name := "Add to board") -> void:
	super(on_level)
	_data = item_set
	_name = action_name
	# The pocket resources are made once so a redo brings back the very same objects.
	for spec: PocketSpec in item_set.get("pockets", []):
		_pockets.append(PocketSpec.create(spec.position, spec.width, spec.depth, spec.payout))
	if on_level != null and on_level.is_pachinko():
		for spec: BonusPocketSpec in item_set.get("bonus", []):
			_bonus.append(Items.moved_bonus(spec, Vector2.ZERO))
		for spec: WindmillSpec in item_set.get("windmills", []):
			_windmills.append(spec.moved(Vector2.ZERO))


func get_name() -> String:
	return _name


## How many things this action adds.
func size() -> int:
	return Items.set_size(_data)


func _touched_fields() -> PackedStringArray:
	return PackedStringArray(Items.ITEM_FIELDS)


func _apply() -> void:
	added.clear()
	# Copies: packed arrays are shared by reference, and the setters must see a new value.
	var pins := level.pins.duplicate()
	var pin_pocket := level.pin_pocket.duplicate()
	var pin_special := level.pin_special.duplicate()
	# Older or hand-written files may have short per-pin arrays: line them up first.
	pin_pocket.resize(pins.size())
	pin_special.resize(pins.size())
	for i in range(level.pin_pocket.size(), pins.size()):
		pin_pocket[i] = -1
	var new_pins: PackedVector2Array = _data.get("pins", PackedVector2Array())
	for point in new_pins:
		added.append(Items.make(Items.Kind.PIN, pins.size()))
		pins.append(point)
		pin_pocket.append(-1)
		pin_special.append(0)
	var pockets := level.pockets.duplicate()
	for spec in _pockets:
		var index := pockets.size()
		pockets.append(spec)
		added.append(Items.make(Items.Kind.POCKET, index))
		var stamp := PocketPins.stamp(level, spec)
		var stamped: PackedVector2Array = stamp["pins"]
		var special: PackedByteArray = stamp["special"]
		for j in stamped.size():
			pins.append(stamped[j])
			pin_pocket.append(index)
			pin_special.append(special[j])
	if not _pockets.is_empty():
		level.pockets = pockets
	level.pins = pins
	level.pin_pocket = pin_pocket
	level.pin_special = pin_special
	level.walls = _append_walls(level.walls.duplicate())
	level.holes = _append_points(level.holes.duplicate(), "holes", Items.Kind.HOLE)
	level.ball_starts = _append_points(level.ball_starts.duplicate(), "starts", Items.Kind.START)
	if not _bonus.is_empty():
		var bonus := level.bonus_pockets.duplicate()
		for spec in _bonus:
			bonus.insert(BonusPocketSpec.role_slot(bonus, spec.role), spec)
		level.bonus_pockets = bonus
		for spec in _bonus:
			added.append(Items.make(Items.Kind.BONUS, level.bonus_pockets.find(spec)))
	if not _windmills.is_empty():
		var wheels := level.windmills.duplicate()
		for spec in _windmills:
			added.append(Items.make(Items.Kind.WINDMILL, wheels.size()))
			wheels.append(spec)
		level.windmills = wheels


func _append_walls(walls: PackedVector2Array) -> PackedVector2Array:
	var extra: PackedVector2Array = _data.get("walls", PackedVector2Array())
	for i in range(0, extra.size() - 1, 2):
		added.append(Items.make(Items.Kind.WALL, Items.wall_count(walls)))
		walls.append(extra[i])
		walls.append(extra[i + 1])
	return walls


func _append_points(points: PackedVector2Array, key: String, kind: int) -> PackedVector2Array:
	var new_points: PackedVector2Array = _data.get(key, PackedVector2Array())
	for point in new_points:
		added.append(Vector2i(kind, points.size()))
		points.append(point)
	return points
