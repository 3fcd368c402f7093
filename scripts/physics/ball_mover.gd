extends RefCounted
## The motion stage for one lane of balls: each awake ball moves by its velocity plus its
## ball-ball separation, in substeps short enough that no ball can cross a pin, a wall or
## the ring; each substep runs the narrow phase per shape kind (ring, pins, walls), and
## every contact goes through one response, respond(). Then the ball's rest time, sleep
## and sensors. Internal to scripts/physics: BallWorld has one mover per lane.
##
## A mover reads the last state and writes only the slots of the balls it moves, plus its
## own event and path buffers, which the world merges in lane order; so the result is the
## same for any number of lanes. The ball being moved lives in members (_p, _v, ...) while
## it moves: a GDScript call costs about as much as a contact test, so calls happen per
## substep and per contact, and the per-candidate tests are written out inside the loops.

## Shapes as respond() sees them: the ring holds the ball inside; pins and wall caps are
## round; a wall's flat side does not curve.
enum Surface { RING, PIN, WALL_CAP, WALL_SIDE }

const BallStore := preload("res://scripts/physics/ball_store.gd")
const StaticGeometry := preload("res://scripts/physics/static_geometry.gd")
const BallSensors := preload("res://scripts/physics/ball_sensors.gd")
const BallEvents := preload("res://scripts/physics/ball_events.gd")
const ContactId := preload("res://scripts/physics/contact_id.gd")
const ContactMath := preload("res://scripts/physics/contact_math.gd")
const BallPairs := preload("res://scripts/physics/ball_pairs.gd")
const SpeedRules := preload("res://scripts/physics/speed_rules.gd")

## A substep moves at most this share of the thinnest (ball + feature) radius: a centre
## that enters a shape is then never past the shape's middle, so it leaves on its own side.
const TRAVEL_SHARE := 0.5
## Safety bound on substeps for one ball in one step.
const MAX_SUBSTEPS := 1024
## The hit event each surface queues on a bounce (indexed by Surface).
const HIT_EVENT: Array[int] = [
	BallEvents.Kind.RING_HIT,
	BallEvents.Kind.PIN_HIT,
	BallEvents.Kind.WALL_HIT,
	BallEvents.Kind.WALL_HIT
]
## Distances below this count as zero (px).
const EPS := ContactMath.EPS

## This lane's events of the step, in order (see BallEvents), and its path points.
var events := PackedInt32Array()
var event_speed := PackedFloat32Array()
var trace_ball := PackedInt32Array()
var trace_pos := PackedVector2Array()

# The step's inputs, copied in by begin(): ball arrays (this lane writes its own slots
# only), static geometry (read only) and constants. Members rather than reads through the
# store and geometry objects: a member is one indexed read, a named read a hash lookup.
var _pos := PackedVector2Array()
var _vel := PackedVector2Array()
var _rad := PackedFloat32Array()
var _push := PackedVector2Array()
var _ids := PackedInt32Array()
var _alive := PackedByteArray()
var _asleep := PackedByteArray()
var _rest := PackedFloat32Array()
var _contact_a := PackedInt32Array()
var _contact_b := PackedInt32Array()
var _support_a := PackedVector2Array()
var _support_b := PackedVector2Array()
var _support_ball := PackedVector2Array()
var _sleep_ball_normal := PackedVector2Array()
var _gutter_hits := PackedInt32Array()
var _gutter_time := PackedFloat32Array()
var _goal_mask := PackedInt32Array()
var _zone_mask := PackedInt32Array()
var _cell_keys := PackedInt64Array()
var _g: StaticGeometry
var _zoned := true
var _pin_start := PackedInt32Array()
var _pin_items := PackedInt32Array()
var _pin_item_pos := PackedVector2Array()
var _pin_item_rad := PackedFloat32Array()
var _pin_special := PackedByteArray()
var _pin_pocket := PackedInt32Array()
var _pin_min_speed_x := PackedFloat64Array()
var _wall_start := PackedInt32Array()
var _wall_items := PackedInt32Array()
var _wall_item_a := PackedVector2Array()
var _wall_item_ab := PackedVector2Array()
var _wall_item_inv := PackedFloat32Array()
var _wall_item_rad := PackedFloat32Array()
var _wall_ab := PackedVector2Array()
var _wall_inv_len2 := PackedFloat32Array()
var _has_walls := false
var _has_ring := false
var _ring_center := Vector2.ZERO
var _has_gutter := false
var _has_sensors := false
var _origin := Vector2.ZERO
var _inv_cell := 1.0
var _cols := 1
var _last_cell := Vector2i.ZERO
var _gravity := Vector2.ZERO
## Per-axis rolling friction for one step (px/s), and whether there is any.
var _friction_dt := Vector2.ZERO
var _has_friction := false
var _dt := 0.0
var _max_speed := 0.0
## True when friction or the cap follow the seed's options (see PhysicsTuning).
var _friction_against_gravity := false
var _cap_per_axis := false
var _caps_glance := false
var _pin_e := 0.0
var _wall_e := 0.0
var _keep_tangent := 1.0
var _threshold := 0.0
var _rest_speed2 := 0.0
## 0 while no ball may fall asleep (just after a wake-up).
var _sleep_time := 0.0
## A ball pushed apart by more than a resting ball moves in a step is still settling.
var _settled_push := 0.0
var _gutter_slide_time := 0.0
var _tracing := false
# The ball being moved: slot, position, velocity, radius, substep time, push per substep.
var _i := 0
var _p := Vector2.ZERO
var _v := Vector2.ZERO
var _r := -1.0
var _h := 0.0
var _push_step := Vector2.ZERO
# Contacts of last step (a persisting one slides) and of this one, with their normals.
var _held_a := ContactId.NONE
var _held_b := ContactId.NONE
var _cur_a := ContactId.NONE
var _cur_b := ContactId.NONE
var _n_a := Vector2.ZERO
var _n_b := Vector2.ZERO
## Set when the ball left the world this substep (pocketed or drained).
var _gone := false
# Per-radius limits, cached while consecutive balls share a radius.
var _max_travel := 0.0
var _ring_lim := 0.0
var _ring_lim2 := 0.0


## Takes this step's state and constants and clears the lane's buffers. Called on the
## world's thread before the lanes run; `may_sleep` is false just after a wake-up.
func begin(
	b: BallStore,
	g: StaticGeometry,
	t: PhysicsTuning,
	gravity: Vector2,
	friction: Vector2,
	dt: float,
	may_sleep: bool
) -> void:
	_take_balls(b)
	_take_geometry(g)
	_gravity = gravity
	_friction_dt = friction.max(Vector2.ZERO) * dt
	_has_friction = _friction_dt != Vector2.ZERO
	_dt = dt
	_max_speed = t.max_speed
	_friction_against_gravity = t.friction_against == PhysicsTuning.FrictionAgainst.GRAVITY
	_cap_per_axis = t.speed_cap == PhysicsTuning.SpeedCap.PER_AXIS
	_caps_glance = t.wall_cap_contact == PhysicsTuning.CapContact.GLANCE
	_pin_e = t.restitution
	_wall_e = t.wall_restitution
	_keep_tangent = t.tangent_friction
	_threshold = t.bounce_threshold
	_rest_speed2 = t.rest_speed * t.rest_speed
	_sleep_time = t.sleep_time if may_sleep else 0.0
	_settled_push = t.rest_speed * dt
	_gutter_slide_time = t.gutter_slide_time
	_tracing = b.tracing
	_r = -1.0
	events.resize(0)
	event_speed.resize(0)
	trace_ball.resize(0)
	trace_pos.resize(0)


func _take_balls(b: BallStore) -> void:
	_pos = b.pos
	_vel = b.vel
	_rad = b.radius
	_push = b.push
	_ids = b.ids
	_alive = b.alive
	_asleep = b.asleep
	_rest = b.rest
	_contact_a = b.contact_a
	_contact_b = b.contact_b
	_support_a = b.support_static
	_support_b = b.support_static2
	_support_ball = b.support_ball
	_sleep_ball_normal = b.sleep_ball_normal
	_gutter_hits = b.gutter_hits
	_gutter_time = b.gutter_time
	_goal_mask = b.goal_mask
	_zone_mask = b.zone_mask
	_cell_keys = b.cell_keys


func _take_geometry(g: StaticGeometry) -> void:
	_g = g
	_zoned = g.zoned
	_pin_start = g.pin_start
	_pin_items = g.pin_items if g.zoned else g.all_pins
	_pin_item_pos = g.pin_item_pos if g.zoned else g.pin_pos
	_pin_item_rad = g.pin_item_radius if g.zoned else g.pin_radius
	_pin_special = g.pin_special
	_pin_pocket = g.pin_pocket
	_pin_min_speed_x = g.pin_min_speed_x
	_wall_start = g.wall_start
	_wall_items = g.wall_items
	_wall_item_a = g.wall_item_a
	_wall_item_ab = g.wall_item_ab
	_wall_item_inv = g.wall_item_inv
	_wall_item_rad = g.wall_item_radius
	_wall_ab = g.wall_ab
	_wall_inv_len2 = g.wall_inv_len2
	_has_walls = not g.wall_a.is_empty()
	_has_ring = g.has_ring
	_ring_center = g.ring_center
	_has_gutter = g.has_gutter
	_has_sensors = not (g.hole_pos.is_empty() and g.goal_pos.is_empty() and g.zone_pos.is_empty())
	_origin = g.origin
	_inv_cell = g.inv_cell
	_cols = g.cols
	_last_cell = Vector2i(g.cols - 1, g.rows - 1)


## Moves the awake balls in slots from..to.
func move_range(from: int, to: int) -> void:
	for i: int in range(from, to):
		if _asleep[i] == 0:
			_move_ball(i)


## One ball through the step: friction and the speed cap, then substeps (each: move, then
## the narrow phase per shape kind), then its contacts, rest, sleep and sensors. The pin
## candidates are tested inline (a call costs as much as a test); contacts call respond().
func _move_ball(i: int) -> void:
	_i = i
	_p = _pos[i]
	_v = _vel[i]
	_gone = false
	_held_a = _contact_a[i]
	_held_b = _contact_b[i]
	_cur_a = ContactId.NONE
	_cur_b = ContactId.NONE
	_n_a = Vector2.ZERO
	_n_b = Vector2.ZERO
	if _friction_against_gravity or _cap_per_axis:
		if _friction_against_gravity:
			_v = SpeedRules.friction_against_gravity(_v, _gravity * _dt, _friction_dt)
		elif _has_friction:
			_v -= _v.clamp(-_friction_dt, _friction_dt)
		_v = SpeedRules.capped(_v, _max_speed, _cap_per_axis)
	else:
		if _has_friction:
			# v - clamp(v, -f, f) slows each axis by up to f and never past zero.
			_v -= _v.clamp(-_friction_dt, _friction_dt)
		var speed2: float = _v.length_squared()
		if speed2 > _max_speed * _max_speed:
			_v *= _max_speed / sqrt(speed2)
	if _rad[i] != _r:
		_set_radius(_rad[i])
	# Substeps: each moves at most the safe travel (velocity plus the ball-ball push, the
	# push capped at half the radius).
	var push: Vector2 = _push[i]
	var push_len := 0.0
	if push != Vector2.ZERO:
		push_len = push.length()
		if push_len > 0.5 * _r:
			push *= 0.5 * _r / push_len
			push_len = 0.5 * _r
	var steps := 1
	var travel: float = (_v * _dt + push).length() + push_len
	if travel > _max_travel:
		steps = mini(ceili(travel / _max_travel), MAX_SUBSTEPS)
	_h = _dt / steps
	_push_step = push / steps
	var p_start: Vector2 = _p
	for sub: int in steps:
		if _tracing and sub > 0:
			trace_ball.append(i)
			trace_pos.append(_p)
		_p += _v * _h + _push_step
		if _has_ring and (_p - _ring_center).length_squared() > _ring_lim2:
			_touch_ring()
		var k0 := 0
		var k1: int = _pin_items.size()
		if _zoned:
			var cell: Vector2i = Vector2i((_p - _origin) * _inv_cell).clamp(
				Vector2i.ZERO, _last_cell
			)
			k0 = _pin_start[cell.y * _cols + cell.x]
			k1 = _pin_start[cell.y * _cols + cell.x + 1]
		for k: int in range(k0, k1):
			var d: Vector2 = _p - _pin_item_pos[k]
			var lim: float = _pin_item_rad[k] + _r
			if d.length_squared() < lim * lim and not _gone:
				_touch_pin(k, d, lim)
		if _has_walls and not _gone:
			# The pins may have moved the ball: the walls of its cell now, if it has any.
			var cell: Vector2i = Vector2i((_p - _origin) * _inv_cell).clamp(
				Vector2i.ZERO, _last_cell
			)
			var c: int = cell.y * _cols + cell.x
			if _wall_start[c] < _wall_start[c + 1]:
				_touch_walls(_wall_start[c], _wall_start[c + 1])
		if _gone:
			break
	_end_ball(i, p_start)


## Writes back ball `i` after its substeps: contacts, position, velocity, rest and sleep,
## then its sensors (which may remove it).
func _end_ball(i: int, p_start: Vector2) -> void:
	# A ball touching nothing now or last step has nothing to update: it saves writes for
	# most of a flowing board.
	if _cur_a != ContactId.NONE or _held_a != ContactId.NONE:
		_contact_a[i] = _cur_a
		_contact_b[i] = _cur_b
		_support_a[i] = _n_a
		_support_b[i] = _n_b
	_pos[i] = _p
	_vel[i] = _v
	# The broad phase's key for next step (see BallStore.cell_keys).
	var cell: Vector2i = Vector2i((_p - _origin) * _inv_cell).clamp(Vector2i.ZERO, _last_cell)
	_cell_keys[i] = ((cell.y * _cols + cell.x) << BallPairs.SORT_SHIFT) | i
	if _gone:
		_alive[i] = 0
		return
	if _v.length_squared() >= _rest_speed2:
		_rest[i] = 0.0
	else:
		_rest_or_sleep(i)
	if _has_sensors:
		var id: int = _ids[i]
		if BallSensors.sense(_g, i, id, p_start, _p, _goal_mask, _zone_mask, events, event_speed):
			_alive[i] = 0


## The limits that depend on the ball radius (kept while consecutive balls share one).
func _set_radius(r: float) -> void:
	_r = r
	_max_travel = _g.max_travel(r, TRAVEL_SHARE)
	_ring_lim = maxf(_g.ring_radius - r, 0.0)
	_ring_lim2 = _ring_lim * _ring_lim


## Narrow phase, ring: the ball's centre stays within ring radius - r of the centre.
## Called only when it is past that. In the gutter arc a bounce counts toward draining,
## and so does time spent rolling there.
func _touch_ring() -> void:
	var d: Vector2 = _p - _ring_center
	var dist: float = sqrt(d.length_squared())
	var nrm: Vector2 = -d / dist
	_p = _ring_center + d * (_ring_lim / dist)
	var bounced: bool = respond(ContactId.RING, _ring_center, d, nrm, _ring_lim, Surface.RING, 0)
	if not _has_gutter or not _g.in_gutter(d):
		return
	if bounced:
		_gutter_hits[_i] += 1
	_gutter_time[_i] += _h
	if _gutter_hits[_i] >= _g.gutter_bounces or _gutter_time[_i] >= _gutter_slide_time:
		_queue(BallEvents.Kind.DRAINED, 0, 0.0)
		_gone = true


## Narrow phase, pins: the ball overlaps pin list entry `k` (offset `d` from its centre,
## contact distance `lim`). A special pin pockets the ball; after touching any other, the
## ball keeps the pin's minimum horizontal speed.
func _touch_pin(k: int, d: Vector2, lim: float) -> void:
	var pin: int = _pin_items[k]
	if _pin_special[pin] != 0:
		_queue(BallEvents.Kind.POCKETED, _pin_pocket[pin], 0.0)
		_gone = true
		return
	var d2: float = d.length_squared()
	var nrm := Vector2(0.0, -1.0)
	if d2 > EPS * EPS:
		nrm = d / sqrt(d2)
	var id: int = (pin << ContactId.KIND_BITS) | ContactId.KIND_PIN
	_p = _pin_item_pos[k] + nrm * lim
	respond(id, _pin_item_pos[k], d, nrm, lim, Surface.PIN, pin)
	var min_speed_x: float = _pin_min_speed_x[pin]
	if absf(_v.x) < min_speed_x:
		_v.x = min_speed_x if _v.x >= 0.0 else -min_speed_x


## Narrow phase, capsule walls: entries k0..k1 of the wall lists (the ball's cell). The
## deepest contact first, then again (up to three times). At a joint the flat side of one
## wall is deeper than the neighbour's cap, so the cap never adds a ghost bump.
func _touch_walls(k0: int, k1: int) -> void:
	for _pass: int in 3:
		var found := 0
		var best := -1
		var best_depth := 0.0
		var best_s := 0.0
		var best_q := Vector2.ZERO
		var best_lim := 0.0
		for k: int in range(k0, k1):
			var a: Vector2 = _wall_item_a[k]
			var ab: Vector2 = _wall_item_ab[k]
			var s: float = clampf((_p - a).dot(ab) * _wall_item_inv[k], 0.0, 1.0)
			var q: Vector2 = a + ab * s
			var lim: float = _wall_item_rad[k] + _r
			var d2: float = _p.distance_squared_to(q)
			if d2 >= lim * lim:
				continue
			found += 1
			var depth: float = lim - sqrt(d2)
			if depth > best_depth or best < 0:
				best = _wall_items[k]
				best_depth = depth
				best_s = s
				best_q = q
				best_lim = lim
		if best < 0:
			return
		_touch_wall(best, best_q, best_s, best_lim)
		if found == 1:
			return


## Answers the contact with wall `wall` at its closest point `q` (at `s` along it).
func _touch_wall(wall: int, q: Vector2, s: float, lim: float) -> void:
	var d: Vector2 = _p - q
	var d2: float = d.length_squared()
	var nrm := Vector2(0.0, -1.0)
	if d2 > EPS * EPS:
		nrm = d / sqrt(d2)
	elif _wall_inv_len2[wall] > 0.0:
		var ab: Vector2 = _wall_ab[wall]
		nrm = Vector2(ab.y, -ab.x).normalized()
	var on_cap: bool = s <= 0.0 or s >= 1.0
	var surface: int = Surface.WALL_CAP if on_cap else Surface.WALL_SIDE
	_p = q + nrm * lim
	respond((wall << ContactId.KIND_BITS) | ContactId.KIND_WALL, q, d, nrm, lim, surface, wall)


## The one contact response, for every surface. The narrow phase has put the ball back on
## the surface (it was at `centre` + `d`, closer than the contact distance `lim`); `nrm`
## points to the free side. Only a ball moving into the surface is answered: a new contact
## faster than the bounce threshold bounces (restitution on the normal speed, tangent
## friction on the rest, with the normal at the moment of impact on a round surface) and
## queues a hit event; a persisting or gentle one slides (see ContactMath.slide). Either
## way it is recorded as a contact (the ball's support). Returns true on a bounce.
func respond(
	id: int, centre: Vector2, d: Vector2, nrm: Vector2, lim: float, surface: int, index: int
) -> bool:
	var vn: float = _v.dot(nrm)
	if vn >= 0.0:
		return false  # already leaving: no bounce, and it presses on nothing
	if surface == Surface.WALL_CAP and _caps_glance:
		return _glance(id, nrm, vn, index)
	var inside: bool = surface == Surface.RING
	var side: float = -1.0 if inside else 1.0
	var bounced := false
	var held: bool = id == _held_a or id == _held_b or id == _cur_a or id == _cur_b
	var gn_dt: float = _gravity.dot(nrm) * _dt
	if not held and minf(gn_dt, 0.0) - vn > _threshold:
		if surface != Surface.WALL_SIDE:
			var back: Vector2 = d - _v * ContactMath.back_off(d, _v, lim, _h, inside)
			if back.length_squared() > EPS:
				nrm = back.normalized() * side
			_p = centre + nrm * (lim * side)
			vn = minf(_v.dot(nrm), 0.0)
		var e: float = _wall_e if surface >= Surface.WALL_CAP else _pin_e
		_v = (_v - nrm * vn) * _keep_tangent - nrm * (vn * e)
		_queue(HIT_EVENT[surface], index, -vn)
		bounced = true
	else:
		var curv := 0.0
		if surface != Surface.WALL_SIDE and lim > EPS:
			curv = _h / lim
		_v = ContactMath.slide(_v, nrm, vn, gn_dt, curv)
	if _cur_a == ContactId.NONE or _cur_a == id:
		_cur_a = id
		_n_a = nrm
	else:
		_cur_b = id
		_n_b = nrm
	return bounced


## A wall cap under CapContact.GLANCE: the ball keeps only its speed along the cap's
## tangent (no bounce, and no turning to follow the curve), so it stops dead head-on and
## otherwise leaves the cap along the tangent. A new contact faster than the bounce
## threshold still queues a hit. Returns true on such a hit.
func _glance(id: int, nrm: Vector2, vn: float, index: int) -> bool:
	var held: bool = id == _held_a or id == _held_b or id == _cur_a or id == _cur_b
	var hit: bool = not held and -vn > _threshold
	if hit:
		_queue(BallEvents.Kind.WALL_HIT, index, -vn)
	_v -= nrm * vn
	if _cur_a == ContactId.NONE or _cur_a == id:
		_cur_a = id
		_n_a = nrm
	else:
		_cur_b = id
		_n_b = nrm
	return hit


## Rest time and sleep of a ball that just moved slower than the rest speed.
func _rest_or_sleep(i: int) -> void:
	var rested: float = _rest[i] + _dt
	_rest[i] = rested
	if _sleep_time <= 0.0 or rested < _sleep_time:
		return
	# A ball still being pushed apart is settling; one lying in the gutter must still drain.
	var push: Vector2 = _push[i]
	if push.length() >= _settled_push or _gutter_time[i] != 0.0 or _gutter_hits[i] != 0:
		return
	var on_ball: Vector2 = _support_ball[i]
	_asleep[i] = BallStore.SLEEP_HELD if on_ball == Vector2.ZERO else BallStore.SLEEP_ON_BALLS
	_sleep_ball_normal[i] = on_ball
	_vel[i] = Vector2.ZERO


func _queue(kind: int, index: int, speed: float) -> void:
	events.append(kind)
	events.append(_ids[_i])
	events.append(index)
	event_speed.append(speed)
