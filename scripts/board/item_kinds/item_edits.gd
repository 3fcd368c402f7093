@tool
class_name ItemEdits
extends RefCounted
## One batch of edits to a BoardLevel's items, shape by shape (ItemKind.Shape): moving,
## mirroring, adding and removing the items of an ItemKind row. Edits write into working
## copies of the board's fields (`work`: field -> copy) that `store` hands back once at the
## end; the row's hooks (`carries`, `turns`, `appended`, `removed`) keep the fields around
## in line. The row is the data; these static helpers are what an edit does with it.


## The copy of `field` that a batch of edits writes into (`work`: field -> copy), made on
## first use. Packed arrays are values, so edits go to one copy a field and `store` hands
## the copies back to the board at the end: one setter call per field, not per item.
static func working(level: BoardLevel, work: Dictionary, field_name: String) -> Variant:
	if not work.has(field_name):
		work[field_name] = unshared_copy(level.get(field_name))
	return work[field_name]


## Hands every copy in `work` back to `level`.
static func store(level: BoardLevel, work: Dictionary) -> void:
	for field_name: String in work:
		level.set(field_name, work[field_name])


## Moves item `index` of `kind` by `by` (and what it carries), writing into `work`.
static func offset(
	kind: ItemKind, level: BoardLevel, work: Dictionary, index: int, by: Vector2
) -> void:
	match kind.shape:
		ItemKind.Shape.POINT:
			var points: PackedVector2Array = working(level, work, kind.field)
			points[index] += by
			work[kind.field] = points
		ItemKind.Shape.SEGMENT:
			var ends: PackedVector2Array = working(level, work, kind.field)
			ends[index * 2] += by
			ends[index * 2 + 1] += by
			work[kind.field] = ends
		ItemKind.Shape.SPEC, ItemKind.Shape.ROLE_SPEC:
			# The resource itself moves: the dock and the inspector hold on to it.
			var specs: Array = level.get(kind.field)
			var spec: Resource = specs[index]
			_move_spec(spec, by)
		ItemKind.Shape.SINGLE:
			var point: Vector2 = working(level, work, kind.field)
			work[kind.field] = point + by
	if kind.carries.is_valid():
		kind.carries.call(level, work, index, by)


## Reflects item `index` across the vertical line x = `axis`, writing into `work`: points
## land at their reflection, a resource's mouth moves there (its shape is symmetrical) and
## the `turns` hook changes the rest.
static func reflect_item(
	kind: ItemKind, level: BoardLevel, work: Dictionary, index: int, axis: float
) -> void:
	match kind.shape:
		ItemKind.Shape.POINT:
			var points: PackedVector2Array = working(level, work, kind.field)
			points[index] = ItemKind.reflect(points[index], axis)
			work[kind.field] = points
		ItemKind.Shape.SEGMENT:
			var ends: PackedVector2Array = working(level, work, kind.field)
			ends[index * 2] = ItemKind.reflect(ends[index * 2], axis)
			ends[index * 2 + 1] = ItemKind.reflect(ends[index * 2 + 1], axis)
			work[kind.field] = ends
		ItemKind.Shape.SINGLE:
			var point: Vector2 = working(level, work, kind.field)
			work[kind.field] = ItemKind.reflect(point, axis)
		_:
			var at := kind.position_of(level, index)
			offset(kind, level, work, index, ItemKind.reflect(at, axis) - at)
			if kind.turns.is_valid():
				var specs: Array = level.get(kind.field)
				kind.turns.call(specs[index])


## Appends one item (a point, a wall's ends as [a, b], a resource) to `work`; the value to
## find it by once every item is in (`index_in`): its index, or the resource itself for a
## ROLE_SPEC item, which goes into its role's slot and so shifts the ones after it.
static func append(kind: ItemKind, level: BoardLevel, work: Dictionary, value: Variant) -> Variant:
	var index := 0
	match kind.shape:
		ItemKind.Shape.POINT:
			var points: PackedVector2Array = working(level, work, kind.field)
			index = points.size()
			var point: Vector2 = value
			points.append(point)
			work[kind.field] = points
		ItemKind.Shape.SEGMENT:
			var ends: PackedVector2Array = working(level, work, kind.field)
			@warning_ignore("integer_division")  # whole segments only
			index = ends.size() / 2
			var pair: Array = value
			var a: Vector2 = pair[0]
			var b: Vector2 = pair[1]
			ends.append(a)
			ends.append(b)
			work[kind.field] = ends
		ItemKind.Shape.SPEC:
			var specs: Array = working(level, work, kind.field)
			index = specs.size()
			specs.append(value)
		ItemKind.Shape.ROLE_SPEC:
			var bonus: Array[BonusPocketSpec] = working(level, work, kind.field)
			bonus.insert(BonusPocketSpec.role_slot(bonus, kind.role), value)
			return value
		ItemKind.Shape.SINGLE:
			return -1
	if kind.appended.is_valid():
		kind.appended.call(level, work, index)
	return index


## Where an item `append` returned `handle` for stands in `work` now.
static func index_in(kind: ItemKind, work: Dictionary, handle: Variant) -> int:
	if handle is int:
		return handle
	var specs: Array = work[kind.field]
	return specs.find(handle)


## Removes the items at `gone` (indices of `field`, sorted) from `work`.
static func remove(
	kind: ItemKind, level: BoardLevel, work: Dictionary, gone: PackedInt32Array
) -> void:
	if gone.is_empty() or kind.shape == ItemKind.Shape.SINGLE:
		return
	if kind.shape == ItemKind.Shape.POINT or kind.shape == ItemKind.Shape.SEGMENT:
		var step := 2 if kind.shape == ItemKind.Shape.SEGMENT else 1
		var points: PackedVector2Array = working(level, work, kind.field)
		var kept_points := PackedVector2Array()
		@warning_ignore("integer_division")  # whole segments only
		for item in points.size() / step:
			if not gone.has(item):
				for k in step:
					kept_points.append(points[item * step + k])
		work[kind.field] = kept_points
	else:
		var specs: Array = working(level, work, kind.field)
		for k in range(gone.size() - 1, -1, -1):
			specs.remove_at(gone[k])
	if kind.removed.is_valid():
		kind.removed.call(level, work, gone)


static func _move_spec(spec: Resource, by: Vector2) -> void:
	var at: Vector2 = spec.get("position")
	spec.set("position", at + by)


## A copy of a board field's value that edits do not share with the board (Arrays and
## packed arrays are shared by reference); other values are copies already. The editor's
## undo snapshots (BoardFieldCopy) copy with it too.
static func unshared_copy(value: Variant) -> Variant:
	match typeof(value):
		TYPE_ARRAY:
			var items: Array = value
			return items.duplicate()
		TYPE_PACKED_VECTOR2_ARRAY:
			var points: PackedVector2Array = value
			return points.duplicate()
		TYPE_PACKED_INT32_ARRAY:
			var numbers: PackedInt32Array = value
			return numbers.duplicate()
		TYPE_PACKED_BYTE_ARRAY:
			var bytes: PackedByteArray = value
			return bytes.duplicate()
	return value
