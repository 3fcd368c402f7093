@tool
extends RefCounted
## Captures and restores a few fields of a BoardLevel, so an action can undo exactly what
## it changed. Arrays are copied: Godot 4 passes packed arrays by reference, so a capture
## that kept the board's own array would change along with it.
##
## Pockets, bonus pockets and windmills are resources that other code (the dock, the
## inspector) may hold on to, so a capture keeps the same objects and the values their
## ItemKinds row names (`spec_values`), and a restore puts both back.


## The values of `fields` on `level`, ready for `restore()`.
static func capture(level: BoardLevel, fields: PackedStringArray) -> Dictionary:
	var snap := {}
	for field in fields:
		var values := _spec_values(field)
		if values.is_empty():
			snap[field] = ItemEdits.unshared_copy(level.get(field))
			continue
		var kept: Array = []
		for spec: Resource in level.get(field):
			var entry: Array = [spec]
			for value in values:
				entry.append(spec.get(value) if spec != null else null)
			kept.append(entry)
		snap[field] = kept
	return snap


## Puts every captured field back on `level`.
static func restore(level: BoardLevel, snap: Dictionary) -> void:
	for field: String in snap:
		var values := _spec_values(field)
		if values.is_empty():
			level.set(field, ItemEdits.unshared_copy(snap[field]))
			continue
		# The field's own typed array, emptied: the board's setter takes only its own type.
		var specs: Array = ItemEdits.unshared_copy(level.get(field))
		specs.clear()
		for entry: Array in snap[field]:
			var spec: Resource = entry[0]
			if spec != null:
				for k in values.size():
					spec.set(values[k], entry[k + 1])
			specs.append(spec)
		level.set(field, specs)


# The resource properties a capture keeps for each item of `field` (its ItemKinds row's
# spec_values); empty for a field that is a plain value.
static func _spec_values(field: String) -> PackedStringArray:
	var kind := ItemKinds.of_field(field)
	return kind.spec_values if kind != null else PackedStringArray()
