@tool
class_name BonusPocketSpec
extends PocketSpec
## One pocket of a pachinko machine's bonus layer: a PocketSpec cup (position, width,
## depth, payout; the depth is at least half the width) with a role. A START pocket spins
## the reels when it catches a ball; an ATTACKER is a wide cup under a lid that opens only
## after a jackpot; a TULIP has two wings that open wide after a catch and close again
## after the next one.
##
## Board files hold one per line: `{"start_pocket": {...}}`, `{"attacker": {...}}`,
## `{"tulip": {...}}` (see board_schema.gd for the fields and their ranges).

enum Role { START, ATTACKER, TULIP }

## The file key of each role, in Role order.
const ROLE_KEYS: Array[String] = ["start_pocket", "attacker", "tulip"]
## Words for each role, in Role order.
const ROLE_NAMES: Array[String] = ["Start pocket", "Attacker", "Tulip"]
## Defaults of the role-specific fields (what a file line may leave out).
const DEFAULT_SYMBOLS := 5
const DEFAULT_OPEN_SECONDS := 8.0
const DEFAULT_OPEN_CATCHES := 10

## What the pocket does when it catches a ball.
@export var role: Role = Role.START:
	set(value):
		role = value
		emit_changed()
## START: symbols on each reel; three equal symbols are a jackpot (odds 1 in symbols²).
@export var symbols: int = DEFAULT_SYMBOLS:
	set(value):
		symbols = value
		emit_changed()
## ATTACKER: the most seconds the lid stays open after a jackpot.
@export var open_seconds: float = DEFAULT_OPEN_SECONDS:
	set(value):
		open_seconds = value
		emit_changed()
## ATTACKER: the lid closes after this many catches, even with time left.
@export var open_catches: int = DEFAULT_OPEN_CATCHES:
	set(value):
		open_catches = value
		emit_changed()


## A bonus pocket of `kind` (a Role) at `at` (a convenience for code, tests and the editor).
## (Not `create`: that is PocketSpec's, without a role.)
static func of_role(
	kind: Role, at: Vector2, mouth_width: float, cup_depth: float, pays: int
) -> BonusPocketSpec:
	var spec := BonusPocketSpec.new()
	spec.role = kind
	spec.position = at
	spec.width = mouth_width
	spec.depth = cup_depth
	spec.payout = pays
	return spec


## The file key for this pocket's role ("start_pocket", "attacker", "tulip").
func role_key() -> String:
	return ROLE_KEYS[role]


## The catching cup as a plain PocketSpec (for PocketStamp and drawing).
func as_pocket() -> PocketSpec:
	return PocketSpec.create(position, width, depth, payout)


## Words for the player and the editor ("Start pocket", "Attacker", "Tulip").
func role_name() -> String:
	return ROLE_NAMES[role]


## Where a new bonus pocket of `new_role` goes in `pockets`: after the last one of the same
## or an earlier role, so a board stays in role order (start pockets, attackers, tulips), the
## order its file stores them in.
static func role_slot(pockets: Array[BonusPocketSpec], new_role: int) -> int:
	var slot := 0
	for i in pockets.size():
		if pockets[i] != null and pockets[i].role <= new_role:
			slot = i + 1
	return slot
