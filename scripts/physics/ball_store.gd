class_name BallStore
extends RefCounted
## The balls of a BallWorld as a struct of arrays (one Packed array per field, one slot per
## live ball, dense, in spawn order). Internal to scripts/physics.
##
## The fields are BallFields.TABLE, and add(), compact() and own_buffers() go by the
## table, so they need no edit for a new field. Each row the engine names has its typed
## array here, of the same name (typed code reads `b.pos`); a row without one is kept in a
## column of its own all the same (column()).
##
## Ids are stable and never reused; `index_of` maps an id to its slot (-1 when gone).
## Removal during a step only clears `alive` (a lane may do it for its own balls);
## `compact()` closes the gaps afterwards, keeping order, so the same inputs always give
## the same layout.

## Values of `asleep` (0 is awake).
const SLEEP_HELD := 1
const SLEEP_ON_BALLS := 2

# The fields of BallFields.TABLE, in its order. STATE first:
var pos := PackedVector2Array()
var vel := PackedVector2Array()
var radius := PackedFloat32Array()
var ids := PackedInt32Array()
var alive := PackedByteArray()
## Seconds the ball's speed has stayed under the tuning's rest speed.
var rest := PackedFloat32Array()
## Nonzero while a ball sleeps: it rested long enough to be skipped until something wakes
## it. SLEEP_HELD: only static shapes (or nothing but friction) hold it; SLEEP_ON_BALLS: a
## ball holds it up too, and it wakes when it touches no ball. Either stays asleep through
## a gravity change its supports can still bear (see BallSleep).
var asleep := PackedByteArray()
## Bounces on the drain arc so far, and seconds of rolling on it.
var drain_hits := PackedInt32Array()
var drain_time := PackedFloat32Array()
## Bit g set while the ball's centre is inside goal g (zones likewise).
var goal_mask := PackedInt32Array()
var zone_mask := PackedInt32Array()
## The static shapes touched last step (two ContactId slots), so a persisting contact
## slides instead of bouncing again.
var contact_a := PackedInt32Array()
var contact_b := PackedInt32Array()
## Support: the normals of the (up to two) static shapes a ball pressed on last step, and
## the normal of a supported ball it pressed on last step (zero if none). A ball backed this
## way does not give way to a ball pushing it into its support, so a stack carries its
## weight at once instead of keeping half of every ball's fall speed. A sleeping ball keeps
## the static normals it fell asleep with: a gravity change is checked against them.
var support_static := PackedVector2Array()
var support_static2 := PackedVector2Array()
var support_ball := PackedVector2Array()
## The normal of the ball a SLEEP_ON_BALLS sleeper rests on, as it fell asleep.
var sleep_ball_normal := PackedVector2Array()
# SCRATCH, rebuilt by each step:
## Extra displacement for this step from ball-ball separation (swept with the motion).
var push := PackedVector2Array()
## The broad-phase keys (cell << BallPairs.SORT_SHIFT | slot), in the order the broad
## phase sorted them last step (sorted_keys): the motion stage rewrites a ball's key there
## when the ball changes cell. So next step's sort starts from an almost sorted array (a
## few balls change cell), which the native sort takes in a tenth of the time of balls in
## slot order. `keys_valid` turns false whenever a ball is placed, added or removed, the
## grid changes or a step runs without ball contacts; the broad phase then bins every ball
## again, in slot order.
var cell_keys := PackedInt64Array()
## The cell in each ball's key in cell_keys.
var key_cell := PackedInt32Array()
## 1 for a ball that touched another ball in this step's ball-ball pass: a sleeper held up
## by balls wakes when it touches none, so it never hangs where a ball was knocked away.
var touching := PackedByteArray()

# Not per slot:
## Slot of each id ever spawned (-1 once removed).
var index_of := PackedInt32Array()
var keys_valid := false
## This step's keys as the broad phase sorted them (and a sentinel), read only after it:
## cell_keys in the same order before the motion stage rewrote any. A moved ball's key is
## found there by binary search (its cell is key_cell), so the broad phase never writes
## where each ball's key went: those writes, one per ball in the order of the keys, made
## two threads' lanes share cache lines.
var sorted_keys := PackedInt64Array()
## True when a copy of a field handed out of the world (handed_out()) may still share its
## buffer: own_buffers() then has work. (add() and compact() resize every array, and a
## resize gives a shared buffer its own copy, so they leave none shared.)
var shared := false
## Set by wake_all(); BallWorld reads and clears it to hold off sleep for a while.
var woken := false
var max_radius := 0.0
## Path recording (for checks, off in play): while `tracing`, each step appends the
## position every ball reached after each of its substeps but the last, as (slot, point).
## The world gathers them here from the lanes until take_step_paths().
var tracing := false
var trace_ball := PackedInt32Array()
var trace_pos := PackedVector2Array()

## The field table this store keeps (BallFields.TABLE but in tests of the table itself).
var _table: Array[Array]
## The columns of rows with no member of their name, by name.
var _unnamed := {}
## The fields handed out since the last own_buffers() (handed_out()).
var _handed: Array[StringName] = []


func _init(table: Array[Array] = BallFields.TABLE) -> void:
	_table = table
	for row: Array in table:
		var name: StringName = row[BallFields.NAME]
		if not name in self:
			_unnamed[name] = BallFields.new_column(row)


func count() -> int:
	return ids.size()


## The array of table field `name` (one slot per ball), or null for a name not in the table.
func column(name: StringName) -> Variant:
	if _unnamed.has(name):
		return _unnamed[name]
	return get(name) if name in self else null


func _set_column(name: StringName, values: Variant) -> void:
	if _unnamed.has(name):
		_unnamed[name] = values
	else:
		set(name, values)


func add(p: Vector2, v: Vector2, r: float) -> int:
	var id: int = index_of.size()
	var slot: int = ids.size()
	index_of.append(slot)
	for row: Array in _table:
		var name: StringName = row[BallFields.NAME]
		var values: Variant = BallFields.resized(column(name), slot + 1)
		values[slot] = row[BallFields.NEW_VALUE]
		_set_column(name, values)
	pos[slot] = p
	vel[slot] = v
	radius[slot] = r
	ids[slot] = id
	keys_valid = false
	max_radius = maxf(max_radius, r)
	return id


## The path points recorded since the last call, {"slots", "points"} (see tracing); clears
## them.
func take_paths() -> Dictionary:
	var out := {"slots": trace_ball, "points": trace_pos}
	trace_ball = PackedInt32Array()
	trace_pos = PackedVector2Array()
	return out


## Index of a live ball by id, or -1.
func find(id: int) -> int:
	if id < 0 or id >= index_of.size():
		return -1
	var i: int = index_of[id]
	if i < 0 or alive[i] == 0:
		return -1
	return i


## Marks slot i dead; compact() removes it.
func kill(i: int) -> void:
	alive[i] = 0


## Removes the balls of `ids` (unknown ones are ignored), closing the gaps once.
func remove(gone: PackedInt32Array) -> void:
	for id: int in gone:
		var i: int = find(id)
		if i >= 0:
			kill(i)
	compact()


## Gives every array the motion lanes write a buffer of its own. Packed arrays are
## copy-on-write: after get_positions() (a duplicate() shares the buffer until one side
## writes), the lanes' first writes would each copy the array at the same time and corrupt
## it. One write here, on the world's thread, makes that copy once, before the lanes run;
## a step with nothing handed out since the last one (`shared` false) has nothing to do.
func own_buffers() -> void:
	if not shared:
		return
	for name: StringName in _handed:
		var values: Variant = column(name)
		if not ids.is_empty():
			values[0] = values[0]
	_handed.clear()
	shared = false


## Returns `copy`, a duplicate() of field `name` going out of the world
## (BallWorld.get_positions() and the other getters), and notes it: it shares the buffer
## until one side writes, so the next own_buffers() must make that field's buffer ours again.
func handed_out(name: StringName, copy: Variant) -> Variant:
	if not name in _handed:
		_handed.append(name)
	shared = true
	return copy


## Wakes every ball (gravity changed, a ball was moved or removed under a pile, ...).
func wake_all() -> void:
	asleep.fill(0)
	woken = true


## Closes the gaps left by dead balls, keeping spawn order. Wakes every ball: a removed
## ball may have been holding sleeping ones up.
func compact() -> void:
	if alive.count(0) == 0:
		return
	var first_gap: int = alive.find(0)
	# The dead slots, last first, so each removal leaves the ones still to go in place.
	var dead := PackedInt32Array()
	for i: int in range(ids.size() - 1, first_gap - 1, -1):
		if alive[i] == 0:
			index_of[ids[i]] = -1
			dead.append(i)
	var n: int = ids.size() - dead.size()
	for row: Array in _table:
		var name: StringName = row[BallFields.NAME]
		var values: Variant = column(name)
		if row[BallFields.PART] == BallFields.Part.STATE:
			# Native removals (a GDScript loop moving every later ball cost about 100 µs
			# per removed ball of a 125-ball analysis world).
			for i: int in dead:
				values = BallFields.without_slot(values, i)
		_set_column(name, BallFields.resized(values, n))
	for w: int in range(first_gap, n):
		index_of[ids[w]] = w
	keys_valid = false
	wake_all()
