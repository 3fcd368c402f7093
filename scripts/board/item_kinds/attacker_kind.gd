@tool
extends RefCounted
## Attackers (BonusPocketSpec ATTACKER): a wide cup under a lid that opens after a jackpot.

const BonusCup := preload("res://scripts/board/item_kinds/bonus_cup.gd")


## The attacker row of ItemKinds.
static func row() -> ItemKind:
	var kind := BonusCup.row(
		BonusPocketSpec.Role.ATTACKER, "attackers", "attacker_ids", "Attackers", 4
	)
	kind.optional_file_fields["open_seconds"] = [
		"float", BoardRanges.BONUS_OPEN_SECONDS[0], BoardRanges.BONUS_OPEN_SECONDS[1]
	]
	kind.optional_file_fields["open_catches"] = [
		"int", BoardRanges.BONUS_OPEN_CATCHES[0], BoardRanges.BONUS_OPEN_CATCHES[1]
	]
	return kind
