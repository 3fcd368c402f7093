@tool
extends RefCounted
## Captures and restores a few fields of a BoardLevel, so an action can undo exactly what
## it changed. Arrays are copied: Godot 4 passes packed arrays by reference, so a capture
## that kept the board's own array would change along with it.
##
## Pockets, bonus pockets and windmills are resources that other code (the dock, the
## inspector) may hold on to, so a capture keeps the same objects and their values, and a
## restore puts both back.

## The BonusPocketSpec fields a capture keeps (its role never changes after it is made).
const BONUS_VALUES: Array[String] = [
	"position", "width", "depth", "payout", "symbols", "open_seconds", "open_catches"
]
## The WindmillSpec fields a capture keeps.
const WINDMILL_VALUES: Array[String] = [
	"position", "blades", "length", "free_spin", "speed", "friction"
]
## Resource lists captured as [object, values...] entries: field -> the values kept.
const SPEC_LISTS := {"bonus_pockets": BONUS_VALUES, "windmills": WINDMILL_VALUES}


## The values of `fields` on `level`, ready for `restore()`.
static func capture(level: BoardLevel, fields: PackedStringArray) -> Dictionary:
	var snap := {}
	for field in fields:
		if field == "pockets":
			var saved: Array = []
			for spec: PocketSpec in level.pockets:
				saved.append([spec, spec.position, spec.width, spec.depth, spec.payout])
			snap[field] = saved
		elif SPEC_LISTS.has(field):
			var values: Array[String] = SPEC_LISTS[field]
			var kept: Array = []
			for spec: Resource in level.get(field):
				var entry: Array = [spec]
				for value in values:
					entry.append(spec.get(value) if spec != null else null)
				kept.append(entry)
			snap[field] = kept
		else:
			snap[field] = _copy(level.get(field))
	return snap


## Puts every captured field back on `level`.
static func restore(level: BoardLevel, snap: Dictionary) -> void:
	for field: String in snap:
		if field == "pockets":
			var specs: Array[PocketSpec] = []
			for entry: Array in snap[field]:
				var spec: PocketSpec = entry[0]
				spec.position = entry[1]
				spec.width = entry[2]
				spec.depth = entry[3]
				spec.payout = entry[4]
				specs.append(spec)
			level.pockets = specs
		elif field == "bonus_pockets":
			var bonus: Array[BonusPocketSpec] = []
			for entry: Array in snap[field]:
				var spec: BonusPocketSpec = entry[0]
				if spec != null:
					for k in BONUS_VALUES.size():
						spec.set(BONUS_VALUES[k], entry[k + 1])
				bonus.append(spec)
			level.bonus_pockets = bonus
		elif field == "windmills":
			var wheels: Array[WindmillSpec] = []
			for entry: Array in snap[field]:
				var spec: WindmillSpec = entry[0]
				if spec != null:
					for k in WINDMILL_VALUES.size():
						spec.set(WINDMILL_VALUES[k], entry[k + 1])
				wheels.append(spec)
			level.windmills = wheels
		else:
			level.set(field, _copy(snap[field]))


static func _copy(value: Variant) -> Variant:
	match typeof(value):
		TYPE_PACKED_VECTOR2_ARRAY:
			var points: PackedVector2Array = value
			return points.duplicate()
		TYPE_PACKED_INT32_ARRAY:
			var numbers: PackedInt32Array = value
			return numbers.duplicate()
		TYPE_PACKED_BYTE_ARRAY:
			var bytes: PackedByteArray = value
			return bytes.duplicate()
		TYPE_ARRAY:
			var items: Array = value
			return items.duplicate()
	return value
