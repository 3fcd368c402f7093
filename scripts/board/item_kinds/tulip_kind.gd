@tool
extends RefCounted
## Tulips (BonusPocketSpec TULIP): two wings that open wide after a catch and close again
## after the next one.

const BonusCup := preload("res://scripts/board/item_kinds/bonus_cup.gd")


## The tulip row of ItemKinds.
static func row() -> ItemKind:
	return BonusCup.row(BonusPocketSpec.Role.TULIP, "tulips", "tulip_ids", "Tulips", 32)
