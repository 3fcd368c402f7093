@tool
class_name TulipKind
extends RefCounted
## Tulips (BonusPocketSpec TULIP): two wings that open wide after a catch and close again
## after the next one.


## The tulip row of ItemKinds.
static func row() -> ItemKind:
	return BonusCup.row(BonusPocketSpec.Role.TULIP, "tulips", "tulip_ids", "Tulips", 32)
