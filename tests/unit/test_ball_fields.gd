extends GutTest
## The per-ball field table (BallFields.TABLE) is the one place a ball field is declared:
## a row alone is stored, kept with its ball through compact() and grown by add(); the
## store's typed arrays and the stages' copies follow the table.

const SPAWNED := 9
## Slots removed before compact(): the first, two in the middle and the last.
const KILLED: Array[int] = [0, 3, 4, 8]


## A value for ball `id` in a column of `type`, different for every id.
func _mark(type: int, id: int) -> Variant:
	match type:
		TYPE_PACKED_VECTOR2_ARRAY:
			return Vector2(id + 1, -(id + 1))
		TYPE_PACKED_FLOAT32_ARRAY:
			return float(id) + 0.5
		TYPE_PACKED_BYTE_ARRAY:
			return id + 1
	return id + 100


## A store with SPAWNED balls whose every table field holds its ball's mark.
func _marked_store(table: Array[Array]) -> BallStore:
	var b := BallStore.new(table)
	for k: int in SPAWNED:
		b.add(Vector2(k, 0), Vector2.ZERO, 5.0)
	for row: Array in table:
		# The ids are what the marks follow; `alive` says which balls stay.
		if row[BallFields.NAME] in [&"ids", &"alive"]:
			continue
		var values: Variant = b.column(row[BallFields.NAME])
		for i: int in SPAWNED:
			values[i] = _mark(row[BallFields.TYPE], b.ids[i])
	for i: int in KILLED:
		b.kill(i)
	return b


func _assert_aligned(b: BallStore, table: Array[Array]) -> void:
	var left: int = SPAWNED - KILLED.size()
	assert_eq(b.count(), left)
	for row: Array in table:
		var name: StringName = row[BallFields.NAME]
		var values: Variant = b.column(name)
		assert_eq(values.size(), left, "%s has one slot per ball left" % name)
		if name == &"asleep":
			assert_eq(
				values.count(0), left, "compact() wakes every ball (one may have held others)"
			)
			continue
		if row[BallFields.PART] != BallFields.Part.STATE or name in [&"ids", &"alive"]:
			continue
		for i: int in left:
			var want: Variant = _mark(row[BallFields.TYPE], b.ids[i])
			assert_eq(values[i], want, "%s of ball %d moved with it" % [name, b.ids[i]])


func test_compact_keeps_every_state_field_with_its_ball() -> void:
	var b := _marked_store(BallFields.TABLE)
	b.compact()
	_assert_aligned(b, BallFields.TABLE)
	for i: int in b.count():
		assert_eq(b.find(b.ids[i]), i, "ids find their new slots")
	for i: int in KILLED:
		assert_eq(b.find(i), -1, "removed ball %d is gone" % i)


func test_a_row_added_to_the_table_is_enough() -> void:
	var table: Array[Array] = BallFields.TABLE.duplicate()
	table.append([&"test_only_charge", BallFields.Part.STATE, TYPE_PACKED_FLOAT32_ARRAY, 2.5])
	table.append([&"test_only_scratch", BallFields.Part.SCRATCH, TYPE_PACKED_INT64_ARRAY, 7])
	var fresh := BallStore.new(table)
	fresh.add(Vector2.ZERO, Vector2.ZERO, 5.0)
	assert_eq(fresh.column(&"test_only_charge"), PackedFloat32Array([2.5]), "a new ball's value")
	assert_eq(fresh.column(&"test_only_scratch"), PackedInt64Array([7]))
	var b := _marked_store(table)
	b.compact()
	_assert_aligned(b, table)


func test_store_arrays_and_table_agree_in_name_type_and_order() -> void:
	var b := BallStore.new()
	b.add(Vector2.ZERO, Vector2.ZERO, 5.0)
	b.add(Vector2.ONE, Vector2.ZERO, 5.0)
	b.kill(0)
	b.compact()
	var named: Array[StringName] = []
	for property: Dictionary in b.get_property_list():
		var name := StringName(property["name"])
		if not (property["usage"] & PROPERTY_USAGE_SCRIPT_VARIABLE) or name.begins_with("_"):
			continue
		var value: Variant = b.get(name)
		var packed: bool = typeof(value) >= TYPE_PACKED_BYTE_ARRAY
		# index_of has a slot per id ever spawned (2 here), the trace arrays none.
		if packed and value.size() == b.count():
			named.append(name)
	var in_table: Array[StringName] = []
	for row: Array in BallFields.TABLE:
		var name: StringName = row[BallFields.NAME]
		in_table.append(name)
		assert_eq(typeof(b.get(name)), row[BallFields.TYPE], "%s has the table's type" % name)
	assert_eq(named, in_table, "every per-ball array is a table row, declared in its order")


func test_the_stages_take_every_table_field_they_declare() -> void:
	var b := BallStore.new()
	b.add(Vector2.ZERO, Vector2.ZERO, 5.0)
	var taken := 0
	for stage: Object in [BallMover.new(), BallSolve.new()]:
		BallFields.take(b, stage)
		for row: Array in BallFields.TABLE:
			var member := StringName("_" + String(row[BallFields.NAME]))
			if member in stage:
				taken += 1
				assert_eq(stage.get(member), b.column(row[BallFields.NAME]), String(member))
	assert_gt(taken, 20, "the mover and the solve read most fields through the table")


func test_the_written_out_takes_share_every_declared_field_with_the_store() -> void:
	# The mover and the solve take their rows member by member (BallFields.take() written
	# out, for speed): each must hold the store's very array (a lane writes through it),
	# for every row it declares, as take() would.
	var b := BallStore.new()
	b.add(Vector2.ZERO, Vector2.ZERO, 5.0)
	for stage: Object in [BallMover.new(), BallSolve.new()]:
		stage.call(&"_take_balls", b)
		var declared := 0
		for row: Array in BallFields.TABLE:
			var name: StringName = row[BallFields.NAME]
			var member := StringName("_" + String(name))
			if member in stage:
				declared += 1
				assert_true(is_same(stage.get(member), b.column(name)), "%s shared" % member)
		assert_gt(declared, 9, "the stage declares its rows")


## In the Godot editor a script that is not @tool never runs its static initializers, so
## BallFields' member list stays empty there; the editor's play analysis (the rail climb,
## the shot chunks, the maze pilot) steps BallWorlds all the same. Before the fix every
## step failed there with "Out of bounds get index '0'" and no ball moved.
func test_balls_move_when_static_initializers_did_not_run_as_in_the_editor() -> void:
	var members_as_loaded: Array[StringName] = BallFields._members
	var plain := _one_falling_ball()
	for i in 10:
		plain.step(1.0 / 60.0)
	BallFields._members = [] as Array[StringName]
	var as_in_editor := _one_falling_ball()
	for i in 10:
		as_in_editor.step(1.0 / 60.0)
	BallFields._members = members_as_loaded
	assert_gt(as_in_editor.get_ball_position(0).y, 100.0, "the ball fell")
	assert_eq(as_in_editor.state_hash(), plain.state_hash(), "the same step as in a game")


func _one_falling_ball() -> BallWorld:
	var world := BallWorld.new()
	world.spawn_ball(Vector2(100, 100), Vector2.ZERO, 5.0)
	return world
