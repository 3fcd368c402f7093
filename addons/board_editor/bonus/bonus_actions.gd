@tool
extends RefCounted
## The undoable edits of the bonus layer: add a bonus pocket (and its mirror image), remove
## one, or change its role (its numbers change through ItemProperties and its row). They keep
## `level.bonus_pockets` in role order (start pockets, attackers, tulips), the order a board
## file stores them in, so a saved board reads back the same.


## Adds bonus pockets; `added` holds their indices after `do()`.
class AddBonus:
	extends BoardAction

	## Indices of the new pockets after the last `do()`.
	var added: PackedInt32Array = PackedInt32Array()
	var _specs: Array[BonusPocketSpec] = []

	## `spec` at its position, plus its mirror image across `mirror_axis` (NAN for none;
	## a pocket on the axis is not doubled).
	func _init(on_level: BoardLevel, spec: BonusPocketSpec, mirror_axis: float = NAN) -> void:
		super(on_level)
		_specs.append(spec)
		if not is_nan(mirror_axis) and absf(spec.position.x - mirror_axis) > spec.width * 0.5:
			var twin := spec.duplicate() as BonusPocketSpec
			twin.position.x = 2.0 * mirror_axis - spec.position.x
			_specs.append(twin)

	func get_name() -> String:
		return "Add %s" % _specs[0].role_name().to_lower()

	func _touched_fields() -> PackedStringArray:
		return PackedStringArray(["bonus_pockets"])

	func _apply() -> void:
		var pockets := level.bonus_pockets.duplicate()
		for spec in _specs:
			pockets.insert(BonusPocketSpec.role_slot(pockets, spec.role), spec)
		level.bonus_pockets = pockets
		added = PackedInt32Array()
		for spec in _specs:
			added.append(level.bonus_pockets.find(spec))


## Removes the bonus pocket at `index` (nothing for an unknown index).
class RemoveBonus:
	extends BoardAction

	var _index: int

	func _init(on_level: BoardLevel, index: int) -> void:
		super(on_level)
		_index = index

	func get_name() -> String:
		return "Remove bonus pocket"

	func _touched_fields() -> PackedStringArray:
		return PackedStringArray(["bonus_pockets"])

	func _apply() -> void:
		if _index < 0 or _index >= level.bonus_pockets.size():
			return
		var pockets := level.bonus_pockets.duplicate()
		pockets.remove_at(_index)
		level.bonus_pockets = pockets


## Turns the bonus pocket at `index` into another role (a tulip into a start pocket...). The
## pocket is replaced by a copy with the new role, moved to its role's place in the list:
## it takes a fresh id in that role's list, and undo brings back the very same pocket with
## its old role and id. The cup (position, size, payout) and the other role fields stay.
class SetBonusRole:
	extends BoardAction

	## Where the pocket is in `level.bonus_pockets` after the last `do()` (-1 if unchanged).
	var moved_to := -1
	var _index: int
	var _role: BonusPocketSpec.Role

	func _init(on_level: BoardLevel, index: int, role: BonusPocketSpec.Role) -> void:
		super(on_level)
		_index = index
		_role = role

	func get_name() -> String:
		return "Make bonus pocket a %s" % BonusPocketSpec.ROLE_NAMES[_role].to_lower()

	func _touched_fields() -> PackedStringArray:
		return PackedStringArray(["bonus_pockets"])

	func _apply() -> void:
		moved_to = -1
		if _index < 0 or _index >= level.bonus_pockets.size():
			push_error("Bonus pocket role: there is no bonus pocket %d." % _index)
			return
		var pockets := level.bonus_pockets.duplicate()
		var original: BonusPocketSpec = level.bonus_pockets[_index]
		var changed := original.duplicate() as BonusPocketSpec
		changed.role = _role
		pockets.remove_at(_index)
		pockets.insert(BonusPocketSpec.role_slot(pockets, _role), changed)
		level.bonus_pockets = pockets
		moved_to = level.bonus_pockets.find(changed)
