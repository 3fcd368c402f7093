@tool
class_name WindmillKind
extends RefCounted
## Windmills (WindmillSpec): wheels of blades the world turns, driven at a speed or spinning
## free with a friction (a file line has one of the two).

## The property panel's keys -> WindmillSpec properties.
const PROPERTIES := {
	"blades": "blades",
	"length": "length",
	"free": "free_spin",
	"speed": "speed",
	"friction": "friction"
}


## The windmill row of ItemKinds.
static func row() -> ItemKind:
	var kind := ItemKind.make("windmill", "windmills", ItemKind.Shape.SPEC)
	kind.list = "windmills"
	kind.id_field = "windmill_ids"
	kind.game = BoardLevel.Kind.PACHINKO
	kind.pick = ItemKind.Pick.WINDMILL
	kind.singular = "Windmill"
	kind.plural = "Windmills"
	kind.set_key = "windmills"
	kind.spec_values = PackedStringArray(
		["position", "blades", "length", "free_spin", "speed", "friction"]
	)
	kind.max_items = 64
	kind.file_fields = {
		"x": ["coord"],
		"y": ["coord"],
		"blades": ["int", WindmillSpec.BLADES_RANGE.x, WindmillSpec.BLADES_RANGE.y],
		"length": ["float", WindmillSpec.LENGTH_RANGE.x, WindmillSpec.LENGTH_RANGE.y],
	}
	kind.optional_file_fields = {
		"id": ["int", 1, ItemKind.MAX_ID],
		"speed": ["float", -WindmillSpec.MAX_SPEED, WindmillSpec.MAX_SPEED],
		"friction": ["float", 0.0, WindmillSpec.MAX_FRICTION],
	}
	kind.turns = turn_back
	kind.checks = check_drive
	kind.reads = _read
	kind.writes = _write
	kind.layer = "Windmills"
	kind.paint_layer = "WINDMILLS"
	kind.placed_by_click = true
	kind.creates = new_windmill
	kind.outlines = _sweep
	kind.properties = _fields
	kind.edits = _set_field
	return kind


static func _set_field(level: BoardLevel, index: int, key: String, value: float) -> void:
	var property: String = PROPERTIES.get(key, "")
	if not property.is_empty():
		ItemKind.set_number(level.windmills[index], property, value)


## The windmill a click places at `at`: four blades turning clockwise (WindmillSpec's
## defaults; the property panel changes them).
static func new_windmill(at: Vector2) -> WindmillSpec:
	return WindmillSpec.driven(
		at, WindmillSpec.DEFAULT_BLADES, WindmillSpec.DEFAULT_LENGTH, WindmillSpec.DEFAULT_SPEED
	)


# The circle its blades sweep; nearer the pin counts as nearer (blades are thin and turn).
static func _sweep(_level: BoardLevel, spec: WindmillSpec) -> ItemOutline:
	var sweep := ItemOutline.circle(spec.position, spec.sweep_radius())
	sweep.weight = 0.5
	sweep.hollow = true
	return sweep


# Its pin, blades, then speed (driven) or friction (free).
static func _fields(level: BoardLevel, index: int) -> Dictionary:
	var spec := level.windmills[index]
	var values := {
		"x": spec.position.x,
		"y": spec.position.y,
		"blades": float(spec.blades),
		"length": spec.length,
		"free": 1.0 if spec.free_spin else 0.0,
	}
	if spec.free_spin:
		values["friction"] = spec.friction
	else:
		values["speed"] = spec.speed
	return values


static func _read(level: BoardLevel, lines: Array) -> Array:
	var specs: Array[WindmillSpec] = []
	for line: Dictionary in lines:
		var at := Vector2(LineText.float_of(line["x"]), LineText.float_of(line["y"]))
		var blades := LineText.int_of(line["blades"])
		var length := LineText.float_of(line["length"])
		if line.has("friction"):
			var friction := LineText.float_of(line["friction"])
			specs.append(WindmillSpec.spinning_free(at, blades, length, friction))
		else:
			specs.append(WindmillSpec.driven(at, blades, length, LineText.float_of(line["speed"])))
	level.windmills = specs
	return lines


# A driven wheel writes its speed, a free one its friction.
static func _write(level: BoardLevel, index: int) -> String:
	var spec := level.windmills[index]
	var text := (
		'"x": %s, "y": %s, "blades": %d, "length": %s'
		% [
			LineText.number(spec.position.x),
			LineText.number(spec.position.y),
			spec.blades,
			LineText.number(spec.length)
		]
	)
	if spec.free_spin:
		return text + ', "friction": %s' % LineText.number(spec.friction)
	return text + ', "speed": %s' % LineText.number(spec.speed)


## A windmill's file line is driven ("speed") or free ("friction"): exactly one of the two.
static func check_drive(line: Dictionary) -> String:
	var driven := line.has("speed")
	var free := line.has("friction")
	if driven and free:
		return (
			'give "speed" (a driven wheel, degrees a second) or "friction" (a free wheel),'
			+ " not both"
		)
	if not driven and not free:
		return 'needs "speed" (a driven wheel, degrees a second) or "friction" (a free wheel)'
	return ""


## A mirrored windmill turns the other way, so a mirrored board plays the same from both
## sides.
static func turn_back(spec: WindmillSpec) -> void:
	spec.speed = -spec.speed
