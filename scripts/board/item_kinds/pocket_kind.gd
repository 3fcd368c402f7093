@tool
class_name PocketKind
extends RefCounted
## Pockets (PocketSpec): a cup of rim pins with a special pin at its bottom. The pocket line
## is the whole pocket: its pins are stamped from it (PocketStamp) into `BoardLevel.pins`,
## owned through `pin_pocket`, so they move, appear and go with it.


## The pocket row of ItemKinds.
static func row() -> ItemKind:
	var kind := ItemKind.make("pocket", "pockets", ItemKind.Shape.SPEC)
	kind.list = "pockets"
	kind.id_field = "pocket_ids"
	kind.game = BoardLevel.Kind.PACHINKO
	kind.pick = ItemKind.Pick.POCKET
	kind.singular = "Pocket"
	kind.plural = "Pockets"
	kind.set_key = "pockets"
	kind.item_fields = PackedStringArray(["pockets", "pins", "pin_pocket", "pin_special"])
	kind.position_fields = PackedStringArray(["pockets", "pins"])
	kind.spec_values = PackedStringArray(["position", "width", "depth", "payout"])
	kind.max_items = 200
	kind.file_fields = {
		"x": ["coord"],
		"y": ["coord"],
		"width": ["float", 1.0, 500.0],
		"depth": ["float", 1.0, 500.0],
		"payout": ["int", 0, 10000],
	}
	kind.optional_file_fields = {"id": ["int", 1, ItemKind.MAX_ID]}
	kind.reads = _read
	kind.writes = _write
	kind.covers = _cup
	kind.carries = _carry_pins
	kind.appended = _stamp_pins
	kind.removed = _remove_pins
	kind.layer = "Pockets"
	kind.paint_layer = "POCKETS"
	kind.outlines = _body
	kind.properties = _fields
	kind.edits = _resize
	return kind


# A new width, depth or payout; the rim and special pin are stamped again to match.
static func _resize(level: BoardLevel, index: int, key: String, value: float) -> void:
	if key in ["width", "depth", "payout"]:
		ItemKind.set_number(level.pockets[index], key, value)
		PocketStamp.apply(level, index)


# The body from the mouth down to the special pin; the selection frame takes in the rim pins.
static func _body(level: BoardLevel, spec: PocketSpec) -> ItemOutline:
	var top_left := spec.position - Vector2(spec.width * 0.5, 0)
	var body := ItemOutline.boxed(Rect2(top_left, Vector2(spec.width, spec.depth)), spec.position)
	body.margin = level.pin_radius
	return body


static func _fields(level: BoardLevel, index: int) -> Dictionary:
	var spec := level.pockets[index]
	return {
		"x": spec.position.x,
		"y": spec.position.y,
		"width": spec.width,
		"depth": spec.depth,
		"payout": float(spec.payout)
	}


# The pockets, each stamping its rim and special pin after the field pins (read first).
static func _read(level: BoardLevel, lines: Array) -> Array:
	var specs: Array[PocketSpec] = []
	for line: Dictionary in lines:
		var at := Vector2(LineText.float_of(line["x"]), LineText.float_of(line["y"]))
		var width := LineText.float_of(line["width"])
		var depth := LineText.float_of(line["depth"])
		specs.append(PocketSpec.create(at, width, depth, LineText.int_of(line["payout"])))
	level.pockets = specs
	for k in specs.size():
		PocketStamp.apply(level, k)
	return lines


static func _write(level: BoardLevel, index: int) -> String:
	var spec := level.pockets[index]
	return (
		'"x": %s, "y": %s, "width": %s, "depth": %s, "payout": %d'
		% [
			LineText.number(spec.position.x),
			LineText.number(spec.position.y),
			LineText.number(spec.width),
			LineText.number(spec.depth),
			spec.payout
		]
	)


# The cup, its rim pins included.
static func _cup(level: BoardLevel, index: int) -> Rect2:
	var spec := level.pockets[index]
	var top_left := spec.position - Vector2(spec.width * 0.5, 0.0)
	return Rect2(top_left, Vector2(spec.width, spec.depth)).grow(level.pin_radius)


# The rim and special pin move with their pocket.
static func _carry_pins(level: BoardLevel, work: Dictionary, index: int, by: Vector2) -> void:
	var owners: PackedInt32Array = work.get("pin_pocket", level.pin_pocket)
	var pins: PackedVector2Array = ItemEdits.working(level, work, "pins")
	for i in mini(owners.size(), pins.size()):
		if owners[i] == index:
			pins[i] += by
	work["pins"] = pins


# A new pocket stamps its rim pins, then its special pin, after the pins already there.
static func _stamp_pins(level: BoardLevel, work: Dictionary, index: int) -> void:
	var specs: Array = work["pockets"]
	var spec: PocketSpec = specs[index]
	var pins: PackedVector2Array = ItemEdits.working(level, work, "pins")
	PinKind.line_up(level, work, pins.size())
	var owners: PackedInt32Array = work["pin_pocket"]
	var special: PackedByteArray = work["pin_special"]
	var stamped := PocketStamp.rim_pins(spec, level.pin_radius, level.ball_radius)
	for j in stamped.size():
		pins.append(stamped[j])
		owners.append(index)
		special.append(1 if j == stamped.size() - 1 else 0)
	work["pins"] = pins
	work["pin_pocket"] = owners
	work["pin_special"] = special


# A removed pocket's pins go with it; the other pins' pocket indices are renumbered.
static func _remove_pins(level: BoardLevel, work: Dictionary, gone: PackedInt32Array) -> void:
	var pins: PackedVector2Array = ItemEdits.working(level, work, "pins")
	PinKind.line_up(level, work, pins.size())
	var owners: PackedInt32Array = work["pin_pocket"]
	var special: PackedByteArray = work["pin_special"]
	var specs: Array = work["pockets"]
	# Pocket index before -> after, -1 for a removed pocket.
	var renumber := PackedInt32Array()
	var next := 0
	for i in specs.size() + gone.size():
		renumber.append(-1 if gone.has(i) else next)
		next += 0 if gone.has(i) else 1
	var kept_pins := PackedVector2Array()
	var kept_owners := PackedInt32Array()
	var kept_special := PackedByteArray()
	for i in pins.size():
		var owner := owners[i]
		var known := owner >= 0 and owner < renumber.size()
		if known and renumber[owner] < 0:
			continue
		kept_pins.append(pins[i])
		kept_owners.append(renumber[owner] if known else -1)
		kept_special.append(special[i])
	work["pins"] = kept_pins
	work["pin_pocket"] = kept_owners
	work["pin_special"] = kept_special
