class_name BallFields
extends RefCounted
## The per-ball fields of a BallWorld, declared once: TABLE. Internal to scripts/physics.
##
## Like Box2D's body sim and body state, the fields come in two parts. STATE is what a ball
## carries from step to step: compact() moves it with its ball. SCRATCH is rebuilt by each
## step (the stage that fills it says when), so compact() only gives it the new length.
## Every place that handles all fields goes by this table: BallStore.add(), compact() and
## own_buffers(), and the begin() of the motion lanes (BallMover) and of the solve
## (BallSolve), which take each row whose `_name` member they declare.
##
## A new ball field is one row here: the store keeps it, aligned with its ball, from then
## on (tests/unit/test_ball_fields.gd). For typed code to read it as `b.name`, BallStore
## declares the typed array of that name (the test checks type and order agree); a stage
## that reads it per ball declares `_name`.

## Row parts.
enum Part { STATE, SCRATCH }

## Row columns: the field's name (BallStore's member), its part, its Packed array type and
## a new ball's value.
const NAME := 0
const PART := 1
const TYPE := 2
const NEW_VALUE := 3

## The fields. pos, vel, radius and ids take add()'s arguments rather than NEW_VALUE.
const TABLE: Array[Array] = [
	# STATE: a ball's state between steps.
	[&"pos", Part.STATE, TYPE_PACKED_VECTOR2_ARRAY, Vector2.ZERO],
	[&"vel", Part.STATE, TYPE_PACKED_VECTOR2_ARRAY, Vector2.ZERO],
	[&"radius", Part.STATE, TYPE_PACKED_FLOAT32_ARRAY, 0.0],
	[&"ids", Part.STATE, TYPE_PACKED_INT32_ARRAY, 0],
	[&"alive", Part.STATE, TYPE_PACKED_BYTE_ARRAY, 1],
	[&"rest", Part.STATE, TYPE_PACKED_FLOAT32_ARRAY, 0.0],
	[&"asleep", Part.STATE, TYPE_PACKED_BYTE_ARRAY, 0],
	[&"drain_hits", Part.STATE, TYPE_PACKED_INT32_ARRAY, 0],
	[&"drain_time", Part.STATE, TYPE_PACKED_FLOAT32_ARRAY, 0.0],
	[&"goal_mask", Part.STATE, TYPE_PACKED_INT32_ARRAY, 0],
	[&"zone_mask", Part.STATE, TYPE_PACKED_INT32_ARRAY, 0],
	[&"contact_a", Part.STATE, TYPE_PACKED_INT32_ARRAY, 0],
	[&"contact_b", Part.STATE, TYPE_PACKED_INT32_ARRAY, 0],
	[&"support_static", Part.STATE, TYPE_PACKED_VECTOR2_ARRAY, Vector2.ZERO],
	[&"support_static2", Part.STATE, TYPE_PACKED_VECTOR2_ARRAY, Vector2.ZERO],
	[&"support_ball", Part.STATE, TYPE_PACKED_VECTOR2_ARRAY, Vector2.ZERO],
	[&"sleep_ball_normal", Part.STATE, TYPE_PACKED_VECTOR2_ARRAY, Vector2.ZERO],
	# SCRATCH: rebuilt by each step.
	[&"push", Part.SCRATCH, TYPE_PACKED_VECTOR2_ARRAY, Vector2.ZERO],
	[&"cell_keys", Part.SCRATCH, TYPE_PACKED_INT64_ARRAY, 0],
	[&"key_cell", Part.SCRATCH, TYPE_PACKED_INT32_ARRAY, 0],
	[&"touching", Part.SCRATCH, TYPE_PACKED_BYTE_ARRAY, 0],
]

## TABLE's names as the `_name` members a stage copies them into (see take()); filled as
## the class loads, before any lane can read it. In the Godot editor a script that is not
## @tool never runs its static initializers, so there it stays empty (see take()).
static var _members: Array[StringName] = _member_names()


## Copies each of the store `from`'s table arrays into the `_name` member of `to`, where
## `to` declares one (a stage that keeps the fields it reads in members of its own, as an
## indexed member read is cheaper than a named one). The arrays are shared, not copied:
## a lane writes the store's own buffers (see BallStore.own_buffers()). `rows`, when given,
## are the rows `to` declares (rows_declared_by(to), kept by a stage that takes every step:
## asking the object for each name is a lookup a row).
## In the editor (the play analysis) the names are made on each call instead: lanes on
## several threads call this, so it never fills the shared list itself.
static func take(from: Object, to: Object, rows := PackedInt32Array()) -> void:
	var members: Array[StringName] = _names()
	if rows.is_empty():
		rows = rows_declared_by(to)
	for k: int in rows:
		var name: StringName = TABLE[k][NAME]
		to.set(members[k], from.get(name))


## The TABLE rows whose `_name` member `object` declares.
static func rows_declared_by(object: Object) -> PackedInt32Array:
	var members: Array[StringName] = _names()
	var rows := PackedInt32Array()
	for k: int in TABLE.size():
		if members[k] in object:
			rows.append(k)
	return rows


static func _names() -> Array[StringName]:
	return _members if _members.size() == TABLE.size() else _member_names()


## An empty array of a row's type.
static func new_column(row: Array) -> Variant:
	var type: int = row[TYPE]
	return resized(type_convert(null, type), 0)


## `column` (one table array) cut or grown to `size` slots (new ones hold zero). A field
## that is not a Packed array is an error.
static func resized(column: Variant, size: int) -> Variant:
	var out: Variant = null
	match typeof(column):
		TYPE_PACKED_VECTOR2_ARRAY:
			var v2: PackedVector2Array = column
			v2.resize(size)
			out = v2
		TYPE_PACKED_FLOAT32_ARRAY:
			var f32: PackedFloat32Array = column
			f32.resize(size)
			out = f32
		TYPE_PACKED_INT32_ARRAY:
			var i32: PackedInt32Array = column
			i32.resize(size)
			out = i32
		TYPE_PACKED_INT64_ARRAY:
			var i64: PackedInt64Array = column
			i64.resize(size)
			out = i64
		TYPE_PACKED_BYTE_ARRAY:
			var bytes: PackedByteArray = column
			bytes.resize(size)
			out = bytes
		_:
			push_error("BallFields: a ball field must be a Packed array (type %d)" % typeof(column))
	return out


## `column` (one table array) without slot `i`, removed natively. A field that is not a
## Packed array is an error.
static func without_slot(column: Variant, i: int) -> Variant:
	var out: Variant = null
	match typeof(column):
		TYPE_PACKED_VECTOR2_ARRAY:
			var v2: PackedVector2Array = column
			v2.remove_at(i)
			out = v2
		TYPE_PACKED_FLOAT32_ARRAY:
			var f32: PackedFloat32Array = column
			f32.remove_at(i)
			out = f32
		TYPE_PACKED_INT32_ARRAY:
			var i32: PackedInt32Array = column
			i32.remove_at(i)
			out = i32
		TYPE_PACKED_INT64_ARRAY:
			var i64: PackedInt64Array = column
			i64.remove_at(i)
			out = i64
		TYPE_PACKED_BYTE_ARRAY:
			var bytes: PackedByteArray = column
			bytes.remove_at(i)
			out = bytes
		_:
			push_error("BallFields: a ball field must be a Packed array (type %d)" % typeof(column))
	return out


static func _member_names() -> Array[StringName]:
	var out: Array[StringName] = []
	for row: Array in TABLE:
		var name: StringName = row[NAME]
		out.append(StringName("_" + name))
	return out
