@tool
extends RefCounted
## Start pockets (BonusPocketSpec START): a catch spins the reels.

const BonusCup := preload("res://scripts/board/item_kinds/bonus_cup.gd")


## The start pocket row of ItemKinds.
static func row() -> ItemKind:
	var kind := BonusCup.row(
		BonusPocketSpec.Role.START, "start_pockets", "start_pocket_ids", "Start pockets", 4
	)
	kind.optional_file_fields["symbols"] = [
		"int", BoardRanges.BONUS_SYMBOLS[0], BoardRanges.BONUS_SYMBOLS[1]
	]
	return kind
