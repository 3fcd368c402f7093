@tool
class_name PinKind
extends RefCounted
## Pins: a pachinko board's field pins. `BoardLevel.pins` also holds the rim pins its pockets
## stamp (PocketStamp); those are the pocket's, not items of their own: they have no id,
## no line in the file, and a designer picks their pocket, never them.


## The pin row of ItemKinds.
static func row() -> ItemKind:
	var kind := ItemKind.make("pin", "pins", ItemKind.Shape.POINT)
	kind.list = "pins"
	kind.id_field = "pin_ids"
	kind.game = BoardLevel.Kind.PACHINKO
	kind.pick = ItemKind.Pick.PIN
	kind.singular = "Pin"
	kind.plural = "Pins"
	kind.set_key = "pins"
	kind.item_fields = PackedStringArray(["pins", "pin_pocket", "pin_special"])
	kind.max_items = 5000
	# "pocket" and "special" were written by older versions: read and dropped (the pocket
	# line stamps its rim now), so those files still load.
	kind.optional_file_fields = {
		"id": ["int", 1, ItemKind.MAX_ID], "pocket": ["int", 0, 199], "special": ["bool"]
	}
	kind.size_field = "pin_radius"
	kind.layer = "Pins"
	kind.paint_layer = "PINS"
	kind.placed_by_click = true
	kind.ghost_crowds = true
	kind.skips = is_rim_pin
	kind.owner = _pocket_of
	kind.reads = _read
	kind.writes = _write
	kind.appended = _appended
	kind.removed = _removed
	return kind


## True when pin `index` belongs to a pocket (stamped from it, never stored on its own).
static func is_rim_pin(level: BoardLevel, index: int) -> bool:
	return index >= 0 and index < level.pin_pocket.size() and level.pin_pocket[index] >= 0


# Field pins only: a pin line of an older file that names its pocket is that pocket's rim,
# which the pocket line stamps. A pin may be special (flag 1) on its own.
static func _read(level: BoardLevel, lines: Array) -> Array:
	var kept: Array = []
	var pins := PackedVector2Array()
	var owners := PackedInt32Array()
	var special := PackedByteArray()
	for line: Dictionary in lines:
		if line.has("pocket"):
			continue
		kept.append(line)
		pins.append(Vector2(LineText.float_of(line["x"]), LineText.float_of(line["y"])))
		owners.append(-1)
		special.append(1 if line.get("special", false) else 0)
	level.pins = pins
	level.pin_pocket = owners
	level.pin_special = special
	return kept


static func _write(level: BoardLevel, index: int) -> String:
	var pin := level.pins[index]
	var text := '"x": %s, "y": %s' % [LineText.number(pin.x), LineText.number(pin.y)]
	if index < level.pin_special.size() and level.pin_special[index] != 0:
		text += ', "special": true'
	return text


# A rim pin is picked as its pocket.
static func _pocket_of(level: BoardLevel, index: int) -> Vector2i:
	return Vector2i(ItemKind.Pick.POCKET, level.pin_pocket[index])


## The per-pin arrays in `work` padded to `pins` entries: older or hand-written files may
## have short ones (a missing owner is -1: a field pin).
static func line_up(level: BoardLevel, work: Dictionary, pins: int) -> void:
	var owners: PackedInt32Array = ItemEdits.working(level, work, "pin_pocket")
	var special: PackedByteArray = ItemEdits.working(level, work, "pin_special")
	var had := owners.size()
	owners.resize(pins)
	for i in range(had, pins):
		owners[i] = -1
	special.resize(pins)
	work["pin_pocket"] = owners
	work["pin_special"] = special


# A new field pin: no pocket, not special.
static func _appended(level: BoardLevel, work: Dictionary, index: int) -> void:
	line_up(level, work, index)
	var owners: PackedInt32Array = work["pin_pocket"]
	var special: PackedByteArray = work["pin_special"]
	owners.append(-1)
	special.append(0)
	work["pin_pocket"] = owners
	work["pin_special"] = special


# The removed pins' owners and flags go with them.
static func _removed(level: BoardLevel, work: Dictionary, gone: PackedInt32Array) -> void:
	var pins: PackedVector2Array = work["pins"]
	line_up(level, work, pins.size() + gone.size())
	var owners: PackedInt32Array = work["pin_pocket"]
	var special: PackedByteArray = work["pin_special"]
	var kept_owners := PackedInt32Array()
	var kept_special := PackedByteArray()
	for i in owners.size():
		if not gone.has(i):
			kept_owners.append(owners[i])
			kept_special.append(special[i])
	work["pin_pocket"] = kept_owners
	work["pin_special"] = kept_special
