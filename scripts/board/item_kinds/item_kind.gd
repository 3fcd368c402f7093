@tool
class_name ItemKind
extends RefCounted
## One kind of board item (a pin, a wall, a tulip...): one row of the ItemKinds table.
##
## A row says where its items live on a BoardLevel (the list field, the id field), how its
## line in a board file is keyed and checked (the schema rows), how a designer names it, and
## which fields a move or an edit of it changes. Its items are handled by their Shape: every
## kind stored the same way (points, wall segments, resources with a `position`) shares the
## code here, so a kind differs from its shape-mates only by its data and its few hooks
## (a pin's rim pins are not items, a pocket carries its rim pins, a windmill turns the
## other way when mirrored). Each kind is one file in this folder that builds its row.
## A batch of edits (move, mirror, add, remove) goes through ItemEdits, which reads the row.
##
## The editor names an item `Vector2i(pick, index)`; `index` counts in the row's `field`
## (for the bonus pockets: in `bonus_pockets`, all three roles together).

## What the editor's item `Vector2i(pick, index)` names: one value per selectable field.
## The three bonus roles share BONUS, as they share `BoardLevel.bonus_pockets`.
enum Pick { PIN, POCKET, WALL, HOLE, START, GOAL, BONUS, WINDMILL }

## How a kind's items are stored on the board.
enum Shape {
	POINT,  ## a PackedVector2Array, one point per item
	SEGMENT,  ## a PackedVector2Array, two points (a, b) per item
	SPEC,  ## an Array of resources, each with a `position`
	ROLE_SPEC,  ## `bonus_pockets`: the resources of one `role` among the others
	SINGLE,  ## one Vector2 field (the goal)
}

## How a click weighs an item against the others under it (the editor's hit test).
enum PickRank {
	OVER,  ## the nearest of these wins
	UNDER,  ## loses to an item the click is inside (a wall under a pin or a ball start)
	LAST,  ## picked only when nothing else is there (the goal, big round what it holds)
}

## The largest id a file may use (ItemIds).
const MAX_ID := 9_999_999

## The key of its line in a board file (`{"pin": {...}}`); the goal, which has no line of
## its own, is "goal".
var name := ""
## Its ItemIds list, the schema's list name and the editor's selection key ("pins",
## "tulips"); "goal" for the goal.
var list := ""
## The BoardLevel field holding the items ("bonus_pockets" for the three bonus roles).
var field := ""
## The BoardLevel field holding the items' stable ids, "" for an item without ids.
var id_field := ""
## The game whose boards have this kind (BoardLevel.Kind).
var game := BoardLevel.Kind.PACHINKO
## The editor's selection value (Pick); a row that leaves it -1 gets the next free number
## past Pick's (ItemKinds), so a new kind needs no new Pick value.
var pick := -1
## The BonusPocketSpec.Role of a ROLE_SPEC kind, else -1.
var role := -1
## How the items are stored (Shape).
var shape := Shape.POINT
## Names for a designer: "Pin" / "Pins".
var singular := ""
var plural := ""
## Its key in an editor item set (BoardItems.extract: the clipboard, placing, pasting);
## the bonus roles share one.
var set_key := ""
## Every BoardLevel field that adding or deleting one of these items may change.
var item_fields := PackedStringArray()
## Every BoardLevel field that moving or mirroring one of these items may change.
var position_fields := PackedStringArray()
## The resource properties an undo snapshot keeps per item (SPEC, ROLE_SPEC), in order.
var spec_values := PackedStringArray()
## Schema: the most items a file may hold, its item line's required fields and the ones it
## may leave out (field -> [type, min, max], BoardSchema.check_value).
var max_items := 0
var file_fields := {}
var optional_file_fields := {}

## The BoardLevel field holding the size of every item of a POINT or SEGMENT kind (a pin's
## radius, a wall's width), for the area it covers; "" for none.
var size_field := ""

## Hooks, each optional (an invalid Callable does nothing, or leaves the shape's way):
## `(level, index) -> Rect2`: the area item `index` covers (a cup, a sweep); a POINT kind
## covers a circle of its `size_field` radius, a SEGMENT a capsule `size_field` wide.
var covers := Callable()
## `(level, index) -> Vector2i`: for a skipped entry, the item that owns it (a rim pin's
## pocket, `Vector2i(pick, index)`), which a designer picks in its place.
var owner := Callable()
## `(level, index) -> String`: item `index`'s fields as its file line writes them, after its
## id (`"x": 12, "y": 40`); a POINT or SEGMENT kind writes its `file_fields` coordinates.
var writes := Callable()
## `(level, lines: Array) -> Array`: sets `field` from the kind's checked file lines and
## returns the lines whose ids are the items' (a pin line of an older file that names its
## pocket is dropped: the pocket stamps it); a POINT or SEGMENT kind reads its coordinates.
var reads := Callable()
## `(line: Dictionary) -> String`: what is wrong with one item line of a board file beyond
## its fields' types and ranges ("" when nothing; a windmill needs a speed or a friction).
var checks := Callable()
## `(level, index) -> bool`: true for an entry of `field` that is not an item of its own
## (a pocket's rim pin).
var skips := Callable()
## `(level, work, index, offset)`: what moves along with item `index` (a pocket's rim pins
## in `work`, see ItemEdits.working).
var carries := Callable()
## `(spec)`: what a mirror image changes besides the place (a windmill turns the other way).
var turns := Callable()
## `(level, work, index)`: keeps other fields in line once item `index` is appended (a pin's
## pocket and special flag, a pocket's stamped rim pins).
var appended := Callable()
## `(level, work, gone)`: removes what belongs to the removed items `gone` (indices before
## the removal, sorted) from the other fields (a pocket's rim pins).
var removed := Callable()

## Editor hooks and settings.
## `(level, value) -> ItemOutline`: the outline of an item given its value (`value_of`), for
## picking, erasing, the selection frame and a place tool's ghost (ItemOutline.of_value); a
## POINT kind is a circle of its `size_field` radius, a SEGMENT a capsule `size_field` wide.
var outlines := Callable()
## How a click weighs these items against the others (PickRank).
var pick_rank := PickRank.OVER
## False for an item the eraser leaves alone (the goal).
var erasable := true
## The editor's layer holding these items ("Pins") and the BoardPainter.Layer flag that
## draws them ("PINS"); rows may share a layer.
var layer := ""
var paint_layer := ""
## `(canvas: CanvasItem, level, index)`: draws item `index` in board pixels, for a kind the
## board painter has no drawing of its own for (a floor arrow); its `paint_layer` shows it.
var paints := Callable()
## True when the editor's place tool puts one of these down per click (a pin, a hole); for
## a SINGLE kind the click moves it.
var placed_by_click := false
## `(at: Vector2) -> Variant`: the item-set value a click at `at` places (a new windmill);
## without it a click places the point.
var creates := Callable()
## A kind with a key here gets its own place tool in the editor (the key picks it), named
## by `singular`, with this tooltip; the kinds the editor has tools for leave it KEY_NONE.
var tool_key := KEY_NONE
var tool_tip := ""
## True when a place tool's ghost turns red where the new item crowds the pins (a pin).
var ghost_crowds := false
## `(level, index) -> Dictionary`: the property panel's fields of item `index` and their
## values (ItemProperties.FIELDS keys); without it a POINT kind shows "x" and "y", a
## SEGMENT its ends "ax", "ay", "bx", "by".
var properties := Callable()
## `(level, index, key, value)`: sets property `key` (not "x" or "y") of item `index`; the
## editor wraps it in one undo step that snapshots `item_fields` and `edit_fields`.
var edits := Callable()
## The BoardLevel fields an `edits` change may touch besides `item_fields` (the goal's
## radius).
var edit_fields := PackedStringArray()


## A fresh row for the `kind_name` line of board files, stored in `level_field`.
static func make(kind_name: String, level_field: String, shape_of: Shape) -> ItemKind:
	var kind := ItemKind.new()
	kind.name = kind_name
	kind.field = level_field
	kind.shape = shape_of
	kind.item_fields = PackedStringArray([level_field])
	kind.position_fields = PackedStringArray([level_field])
	kind.file_fields = {"x": ["coord"], "y": ["coord"]}
	return kind


## Sets `property` of the item resource `spec` to the number `value` typed as the property
## is: a whole number rounded, a yes/no from 0 or 1 (the property panel types numbers).
static func set_number(spec: Resource, property: String, value: float) -> void:
	var current: Variant = spec.get(property)
	if current is bool:
		spec.set(property, value >= 0.5)
	elif current is int:
		spec.set(property, roundi(value))
	else:
		spec.set(property, value)


## `point` reflected across the vertical line x = `axis`.
static func reflect(point: Vector2, axis: float) -> Vector2:
	return Vector2(2.0 * axis - point.x, point.y)


## True when this kind has stable ids (every kind but the goal).
func has_ids() -> bool:
	return not id_field.is_empty()


## How many items of this kind `level` holds (skipped entries included: ids line up with
## the field).
func count(level: BoardLevel) -> int:
	match shape:
		Shape.POINT, Shape.SEGMENT:
			var points: PackedVector2Array = level.get(field)
			@warning_ignore("integer_division")  # whole segments only
			return points.size() / 2 if shape == Shape.SEGMENT else points.size()
		Shape.SPEC:
			var specs: Array = level.get(field)
			return specs.size()
		Shape.ROLE_SPEC:
			return field_indices(level).size()
	return 1 if level.kind == game else 0


## For ROLE_SPEC: the indices in `field` of this role's items, in board order; for the other
## shapes every index of the field.
func field_indices(level: BoardLevel) -> PackedInt32Array:
	var found := PackedInt32Array()
	if shape != Shape.ROLE_SPEC:
		for i in count(level):
			found.append(i)
		return found
	var specs: Array = level.get(field)
	for i in specs.size():
		var spec: BonusPocketSpec = specs[i]
		if spec != null and spec.role == role:
			found.append(i)
	return found


## True when entry `index` of `field` is an item of this kind on `level` now (indices go
## stale after an undo).
func is_valid(level: BoardLevel, index: int) -> bool:
	if index < 0:
		return false
	match shape:
		Shape.SPEC, Shape.ROLE_SPEC:
			var specs: Array = level.get(field)
			if index >= specs.size() or specs[index] == null:
				return false
			var spec: Resource = specs[index]
			return shape == Shape.SPEC or (spec is BonusPocketSpec and spec.get("role") == role)
		Shape.SINGLE:
			return level.kind == game
	return index < count(level)


## True when entry `index` is an item a designer can pick (not a skipped entry).
func is_item(level: BoardLevel, index: int) -> bool:
	return is_valid(level, index) and not (skips.is_valid() and skips.call(level, index))


## The point that stands for item `index`: a centre, a pocket's mouth, a wall's midpoint.
func position_of(level: BoardLevel, index: int) -> Vector2:
	match shape:
		Shape.POINT:
			var points: PackedVector2Array = level.get(field)
			return points[index]
		Shape.SEGMENT:
			var ends: PackedVector2Array = level.get(field)
			return (ends[index * 2] + ends[index * 2 + 1]) * 0.5
		Shape.SPEC, Shape.ROLE_SPEC:
			var specs: Array = level.get(field)
			var spec: Resource = specs[index]
			return _position(spec)
	var point: Vector2 = level.get(field)
	return point


## Item `index`'s value: a point (POINT, SINGLE), a wall's ends [a, b], a resource.
func value_of(level: BoardLevel, index: int) -> Variant:
	match shape:
		Shape.SEGMENT:
			var ends: PackedVector2Array = level.get(field)
			return [ends[index * 2], ends[index * 2 + 1]]
		Shape.SPEC, Shape.ROLE_SPEC:
			var specs: Array = level.get(field)
			return specs[index]
	return position_of(level, index)


## The area item `index` covers on the board (its pins, cup, capsule or circle).
func extent(level: BoardLevel, index: int) -> Rect2:
	if covers.is_valid():
		return covers.call(level, index)
	var size: float = level.get(size_field) if not size_field.is_empty() else 0.0
	if shape == Shape.SEGMENT:
		var ends: PackedVector2Array = level.get(field)
		var box := Rect2(ends[index * 2], Vector2.ZERO).expand(ends[index * 2 + 1])
		return box.grow(size * 0.5)
	return Rect2(position_of(level, index), Vector2.ZERO).grow(size)


## The points that must lie in a box for item `index` to be boxed: both ends of a wall,
## else the point that stands for it.
func box_points(level: BoardLevel, index: int) -> PackedVector2Array:
	if shape == Shape.SEGMENT:
		var ends: PackedVector2Array = level.get(field)
		return ends.slice(index * 2, index * 2 + 2)
	return PackedVector2Array([position_of(level, index)])


## A copy of one item of an item set (a point, a wall's [a, b] ends, a resource) moved by
## `by`; resources are copied, never shared.
func moved_value(value: Variant, by: Vector2) -> Variant:
	if value is Vector2:
		var point: Vector2 = value
		return point + by
	var spec: Resource = value
	var copy := spec.duplicate()
	_set_position(copy, _position(spec) + by)
	return copy


## The mirror image of one item-set value (see `moved_value`) across x = `axis`.
func reflected_value(value: Variant, axis: float) -> Variant:
	if value is Vector2:
		var point: Vector2 = value
		return reflect(point, axis)
	var spec: Resource = value
	var at := _position(spec)
	var twin: Resource = moved_value(spec, reflect(at, axis) - at)
	if turns.is_valid():
		turns.call(twin)
	return twin


## The item-set values of item `index` (one point, a wall's two ends, a copy of the
## resource), positions relative to `origin`.
func values_of(level: BoardLevel, index: int, origin: Vector2) -> Array:
	match shape:
		Shape.SEGMENT:
			var ends: PackedVector2Array = level.get(field)
			return [ends[index * 2] - origin, ends[index * 2 + 1] - origin]
		Shape.SPEC, Shape.ROLE_SPEC:
			var specs: Array = level.get(field)
			return [moved_value(specs[index], -origin)]
	return [position_of(level, index) - origin]


## Item `index`'s line in a board file, after its id: `"x": 12, "y": 40`.
func line_of(level: BoardLevel, index: int) -> String:
	if writes.is_valid():
		return writes.call(level, index)
	var points: PackedVector2Array = level.get(field)
	var step := 2 if shape == Shape.SEGMENT else 1
	return LineText.coords(file_fields.keys(), points.slice(index * step, index * step + step))


## Sets `field` on a board being built from the kind's checked file `lines`; the lines
## whose ids the items take, in order.
func read_lines(level: BoardLevel, lines: Array) -> Array:
	if reads.is_valid():
		return reads.call(level, lines)
	var points := PackedVector2Array()
	for line: Dictionary in lines:
		points.append_array(LineText.points_of(line, file_fields.keys()))
	level.set(field, points)
	return lines


## What identifies each item of `items` (the `field` value, or its BoardFieldCopy capture
## of [object, values...] entries) across an edit: a point, a wall's [a, b], a resource
## itself (for ROLE_SPEC only this role's).
func keys_of(items: Variant) -> Array:
	var keys: Array = []
	match shape:
		Shape.POINT:
			var points: PackedVector2Array = items
			keys.append_array(Array(points))
		Shape.SEGMENT:
			var ends: PackedVector2Array = items
			for i in range(0, ends.size() - 1, 2):
				keys.append([ends[i], ends[i + 1]])
		Shape.SPEC, Shape.ROLE_SPEC:
			var entries: Array = items
			for entry: Variant in entries:
				var item: Variant = entry
				if entry is Array:
					var captured: Array = entry
					item = captured[0]
				if shape == Shape.SPEC:
					keys.append(item)
				elif item is BonusPocketSpec:
					var spec: BonusPocketSpec = item
					if spec.role == role:
						keys.append(spec)
	return keys


static func _position(spec: Resource) -> Vector2:
	var at: Vector2 = spec.get("position")
	return at


static func _set_position(spec: Resource, at: Vector2) -> void:
	spec.set("position", at)
