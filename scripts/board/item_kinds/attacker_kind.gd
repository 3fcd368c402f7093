@tool
class_name AttackerKind
extends RefCounted
## Attackers (BonusPocketSpec ATTACKER): a wide cup under a lid that opens after a jackpot.


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
	kind.writes = _write
	return kind


static func _write(level: BoardLevel, index: int) -> String:
	var spec := level.bonus_pockets[index]
	return (
		BonusCup.cup_line(level, index)
		+ (
			', "open_seconds": %s, "open_catches": %d'
			% [LineText.number(spec.open_seconds), spec.open_catches]
		)
	)
