@tool
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
	return kind
