@tool
class_name BonusCup
extends RefCounted
## What the three bonus pocket kinds (start pocket, attacker, tulip: BonusPocketSpec) share:
## they live together in `BoardLevel.bonus_pockets`, start pockets first, then attackers,
## then tulips, and every one is a cup a 10 px ball fits into, paying a sane amount.

## The BonusPocketSpec fields an undo snapshot keeps (its role never changes after it is made).
const VALUES: Array[String] = [
	"position", "width", "depth", "payout", "symbols", "open_seconds", "open_catches"
]
## The fields every bonus pocket line has.
const FILE_FIELDS := {
	"x": ["coord"],
	"y": ["coord"],
	"width": ["float", 16.0, 160.0],
	"depth": ["float", 8.0, 200.0],
	"payout": ["int", BoardRanges.BONUS_PAYOUT[0], BoardRanges.BONUS_PAYOUT[1]],
}


## The row of the bonus pockets of `role`; its role's own fields are added by its file.
static func row(
	role: BonusPocketSpec.Role, list: String, id_field: String, plural: String, most: int
) -> ItemKind:
	var kind := ItemKind.make(
		BonusPocketSpec.ROLE_KEYS[role], "bonus_pockets", ItemKind.Shape.ROLE_SPEC
	)
	kind.list = list
	kind.id_field = id_field
	kind.game = BoardLevel.Kind.PACHINKO
	kind.pick = ItemKind.Pick.BONUS
	kind.role = role
	kind.singular = BonusPocketSpec.ROLE_NAMES[role]
	kind.plural = plural
	kind.set_key = "bonus"
	kind.spec_values = PackedStringArray(VALUES)
	kind.max_items = most
	kind.file_fields = FILE_FIELDS
	kind.optional_file_fields = {"id": ["int", 1, ItemKind.MAX_ID]}
	kind.reads = read_cups.bind(role)
	kind.writes = cup_line
	kind.covers = _cup
	kind.layer = "Bonus pieces"
	kind.paint_layer = "BONUS"
	kind.outlines = _rimmed_cup
	kind.properties = _fields
	kind.edits = _set_field
	return kind


# The cup's size and payout, or its role's own field (the property panel's keys are the
# BonusPocketSpec properties).
static func _set_field(level: BoardLevel, index: int, key: String, value: float) -> void:
	if key in VALUES and key != "position":
		ItemKind.set_number(level.bonus_pockets[index], key, value)


# The cup with the pins the world stamps round its edge.
static func _rimmed_cup(level: BoardLevel, spec: BonusPocketSpec) -> ItemOutline:
	var grow := maxf(level.pin_radius, 0.0)
	var top_left := spec.position - Vector2(spec.width * 0.5 + grow, grow)
	var size := Vector2(spec.width + grow * 2.0, spec.depth + grow * 2.0)
	return ItemOutline.boxed(Rect2(top_left, size), spec.position)


# The cup's fields, then its role's own.
static func _fields(level: BoardLevel, index: int) -> Dictionary:
	var spec := level.bonus_pockets[index]
	var values := {
		"x": spec.position.x,
		"y": spec.position.y,
		"width": spec.width,
		"depth": spec.depth,
		"payout": float(spec.payout),
	}
	if spec.role == BonusPocketSpec.Role.START:
		values["symbols"] = float(spec.symbols)
	elif spec.role == BonusPocketSpec.Role.ATTACKER:
		values["open_seconds"] = spec.open_seconds
		values["open_catches"] = float(spec.open_catches)
	return values


# The cup (its pins are stamped by the world, round its edge).
static func _cup(level: BoardLevel, index: int) -> Rect2:
	var spec := level.bonus_pockets[index]
	var top_left := spec.position - Vector2(spec.width * 0.5, 0.0)
	return Rect2(top_left, Vector2(spec.width, spec.depth))


## Appends the bonus pockets of `role` from their checked file lines to the board's (the
## rows read in role order, so the board keeps its bonus pockets in role order). A line
## may leave out its role's own fields: the defaults.
static func read_cups(level: BoardLevel, lines: Array, role: BonusPocketSpec.Role) -> Array:
	var specs := level.bonus_pockets.duplicate()
	for line: Dictionary in lines:
		var at := Vector2(LineText.float_of(line["x"]), LineText.float_of(line["y"]))
		var spec := BonusPocketSpec.of_role(
			role,
			at,
			LineText.float_of(line["width"]),
			LineText.float_of(line["depth"]),
			LineText.int_of(line["payout"])
		)
		spec.symbols = LineText.int_of(line.get("symbols", BonusPocketSpec.DEFAULT_SYMBOLS))
		spec.open_seconds = LineText.float_of(
			line.get("open_seconds", BonusPocketSpec.DEFAULT_OPEN_SECONDS)
		)
		spec.open_catches = LineText.int_of(
			line.get("open_catches", BonusPocketSpec.DEFAULT_OPEN_CATCHES)
		)
		specs.append(spec)
	level.bonus_pockets = specs
	return lines


## The cup's part of a bonus pocket's line (`index` in `bonus_pockets`); its role's own
## fields follow.
static func cup_line(level: BoardLevel, index: int) -> String:
	var spec := level.bonus_pockets[index]
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
