@tool
extends RefCounted
## The undoable edits of the bonus layer: add a bonus pocket (and its mirror image) or
## remove one. Both keep `level.bonus_pockets` in role order (start pockets, attackers,
## tulips), the order a board file stores them in, so a saved board reads back the same.


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
			pockets.insert(_slot_for(pockets, spec.role), spec)
		level.bonus_pockets = pockets
		added = PackedInt32Array()
		for spec in _specs:
			added.append(level.bonus_pockets.find(spec))

	# After the last pocket of the same or an earlier role.
	static func _slot_for(pockets: Array[BonusPocketSpec], role: int) -> int:
		var slot := 0
		for i in pockets.size():
			if pockets[i] != null and pockets[i].role <= role:
				slot = i + 1
		return slot


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
