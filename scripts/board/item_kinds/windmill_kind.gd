@tool
extends RefCounted
## Windmills (WindmillSpec): wheels of blades the world turns, driven at a speed or spinning
## free with a friction (a file line has one of the two).


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
	return kind


## A mirrored windmill turns the other way, so a mirrored board plays the same from both
## sides.
static func turn_back(spec: WindmillSpec) -> void:
	spec.speed = -spec.speed
