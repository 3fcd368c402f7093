extends RefCounted
## The balls of a BallWorld as a struct of arrays (one Packed array per field, one slot per
## live ball, dense, in spawn order). Internal to scripts/physics.
##
## Ids are stable and never reused; `index_of` maps an id to its slot (-1 when gone).
## Removal during a step only clears `alive` (a lane may do it for its own balls);
## `compact()` closes the gaps afterwards, keeping order, so the same inputs always give
## the same layout.

const ContactId := preload("res://scripts/physics/contact_id.gd")

## Values of `asleep` (0 is awake).
const SLEEP_HELD := 1
const SLEEP_ON_BALLS := 2

var pos := PackedVector2Array()
var vel := PackedVector2Array()
var radius := PackedFloat32Array()
var ids := PackedInt32Array()
var alive := PackedByteArray()
## Seconds the ball's speed has stayed under the tuning's rest speed.
var rest := PackedFloat32Array()
## Bounces on the drain arc so far, and seconds of rolling on it.
var drain_hits := PackedInt32Array()
var drain_time := PackedFloat32Array()
## Bit g set while the ball's centre is inside goal g (zones likewise).
var goal_mask := PackedInt32Array()
var zone_mask := PackedInt32Array()
## Nonzero while a ball sleeps: it rested long enough to be skipped until something wakes
## it. SLEEP_HELD: only static shapes (or nothing but friction) hold it; SLEEP_ON_BALLS: a
## ball holds it up too, and it wakes when it touches no ball. Either stays asleep through
## a gravity change its supports can still bear (see BallSleep).
var asleep := PackedByteArray()
## Set by wake_all(); BallWorld reads and clears it to hold off sleep for a while.
var woken := false
## Support: the normals of the (up to two) static shapes a ball pressed on last step, and
## the normal of a supported ball it pressed on last step (zero if none). A ball backed this
## way does not give way to a ball pushing it into its support, so a stack carries its
## weight at once instead of keeping half of every ball's fall speed. A sleeping ball keeps
## the static normals it fell asleep with: a gravity change is checked against them.
var support_static := PackedVector2Array()
var support_static2 := PackedVector2Array()
## The normal of the ball a SLEEP_ON_BALLS sleeper rests on, as it fell asleep.
var sleep_ball_normal := PackedVector2Array()
var support_ball := PackedVector2Array()
## Path recording (for checks, off in play): while `tracing`, each step appends the
## position every ball reached after each of its substeps but the last, as (slot, point).
## The world gathers them here from the lanes until take_step_paths().
var tracing := false
var trace_ball := PackedInt32Array()
var trace_pos := PackedVector2Array()
## The static shapes touched last step (two ContactId slots), so a persisting contact
## slides instead of bouncing again.
var contact_a := PackedInt32Array()
var contact_b := PackedInt32Array()
## Extra displacement for this step from ball-ball separation (swept with the motion).
var push := PackedVector2Array()
var index_of := PackedInt32Array()
## Each slot's broad-phase key (cell << BallPairs.SORT_SHIFT | slot), written by the
## motion stage where the ball ended; `keys_valid` turns false whenever a ball is placed,
## added or removed, or the grid changes, and the broad phase then bins every ball again.
var cell_keys := PackedInt64Array()
var keys_valid := false
## 1 for a ball that touched another ball in this step's ball-ball pass: a sleeper held up
## by balls wakes when it touches none, so it never hangs where a ball was knocked away.
var touching := PackedByteArray()
var max_radius := 0.0


func count() -> int:
	return ids.size()


func add(p: Vector2, v: Vector2, r: float) -> int:
	var id: int = index_of.size()
	index_of.append(ids.size())
	pos.append(p)
	vel.append(v)
	radius.append(r)
	ids.append(id)
	alive.append(1)
	rest.append(0.0)
	drain_hits.append(0)
	drain_time.append(0.0)
	goal_mask.append(0)
	zone_mask.append(0)
	contact_a.append(ContactId.NONE)
	contact_b.append(ContactId.NONE)
	push.append(Vector2.ZERO)
	asleep.append(0)
	support_static.append(Vector2.ZERO)
	support_static2.append(Vector2.ZERO)
	sleep_ball_normal.append(Vector2.ZERO)
	support_ball.append(Vector2.ZERO)
	cell_keys.append(0)
	keys_valid = false
	max_radius = maxf(max_radius, r)
	return id


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


## Gives every array the motion lanes write a buffer of its own. Packed arrays are
## copy-on-write: after get_positions() (a duplicate() shares the buffer until one side
## writes), the lanes' first writes would each copy the array at the same time and corrupt
## it. One write here, on the world's thread, makes that copy once, before the lanes run.
func own_buffers() -> void:
	if ids.is_empty():
		return
	pos[0] = pos[0]
	vel[0] = vel[0]
	alive[0] = alive[0]
	asleep[0] = asleep[0]
	rest[0] = rest[0]
	contact_a[0] = contact_a[0]
	contact_b[0] = contact_b[0]
	support_static[0] = support_static[0]
	support_static2[0] = support_static2[0]
	sleep_ball_normal[0] = sleep_ball_normal[0]
	drain_hits[0] = drain_hits[0]
	drain_time[0] = drain_time[0]
	goal_mask[0] = goal_mask[0]
	zone_mask[0] = zone_mask[0]
	cell_keys[0] = cell_keys[0]


## Wakes every ball (gravity changed, a ball was moved or removed under a pile, ...).
func wake_all() -> void:
	asleep.fill(0)
	woken = true


## Closes the gaps left by dead balls, keeping spawn order. Wakes every ball: a removed
## ball may have been holding sleeping ones up.
func compact() -> void:
	if alive.count(0) == 0:
		return
	var n: int = ids.size()
	var w := 0
	for i: int in n:
		if alive[i] == 0:
			index_of[ids[i]] = -1
			continue
		if w != i:
			pos[w] = pos[i]
			vel[w] = vel[i]
			radius[w] = radius[i]
			ids[w] = ids[i]
			alive[w] = 1
			rest[w] = rest[i]
			drain_hits[w] = drain_hits[i]
			drain_time[w] = drain_time[i]
			goal_mask[w] = goal_mask[i]
			zone_mask[w] = zone_mask[i]
			contact_a[w] = contact_a[i]
			contact_b[w] = contact_b[i]
			support_static[w] = support_static[i]
			support_static2[w] = support_static2[i]
			support_ball[w] = support_ball[i]
			index_of[ids[w]] = w
		w += 1
	pos.resize(w)
	vel.resize(w)
	push.resize(w)
	radius.resize(w)
	ids.resize(w)
	alive.resize(w)
	rest.resize(w)
	drain_hits.resize(w)
	drain_time.resize(w)
	goal_mask.resize(w)
	zone_mask.resize(w)
	contact_a.resize(w)
	contact_b.resize(w)
	asleep.resize(w)
	support_static.resize(w)
	support_static2.resize(w)
	sleep_ball_normal.resize(w)
	support_ball.resize(w)
	cell_keys.resize(w)
	keys_valid = false
	wake_all()
