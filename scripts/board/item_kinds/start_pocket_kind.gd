@tool
class_name StartPocketKind
extends RefCounted
## Start pockets (BonusPocketSpec START): a catch spins the reels.


## The start pocket row of ItemKinds.
static func row() -> ItemKind:
	var kind := BonusCup.row(
		BonusPocketSpec.Role.START, "start_pockets", "start_pocket_ids", "Start pockets", 4
	)
	kind.optional_file_fields["symbols"] = [
		"int", BoardRanges.BONUS_SYMBOLS[0], BoardRanges.BONUS_SYMBOLS[1]
	]
	kind.writes = _write
	return kind


static func _write(level: BoardLevel, index: int) -> String:
	var symbols := level.bonus_pockets[index].symbols
	return BonusCup.cup_line(level, index) + ', "symbols": %d' % symbols
