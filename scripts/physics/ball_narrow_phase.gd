extends "res://scripts/physics/ball_mover_state.gd"
## The narrow phase of the motion stage and its one contact response, for the ball being
## moved (in BallMoverState's members): the ring, pins, capsule walls and windmill blades,
## each put back on the surface and answered by respond(). BallMover (the per-lane loop of
## substeps) extends it. Internal to scripts/physics.
##
## Why a class between the state and the loop, not an object the loop holds: every test
## here reads and writes the ball being moved and the step's arrays, and a member read is
## one indexed read where another object's field is a hash lookup; a call through another
## object also costs as much as a contact test. So the loop, the narrow phase and the state
## share one object, and each file keeps one job.

## Shapes as respond() sees them: the ring holds the ball inside; pins and wall and blade
## caps are round; the flat sides (from WALL_SIDE on) do not curve. Blades bounce like walls.
enum Surface { RING, PIN, WALL_CAP, BLADE_CAP, WALL_SIDE, BLADE_SIDE }

const ContactMath := preload("res://scripts/physics/contact_math.gd")
const ContactRule := preload("res://scripts/physics/contact_rule.gd")

## The hit event each surface queues on a bounce (indexed by Surface).
const HIT_EVENT: Array[int] = [
	BallEvents.Kind.RING_HIT,
	BallEvents.Kind.PIN_HIT,
	BallEvents.Kind.WALL_HIT,
	BallEvents.Kind.BLADE_HIT,
	BallEvents.Kind.WALL_HIT,
	BallEvents.Kind.BLADE_HIT
]
## Distances below this count as zero (px).
const EPS := ContactMath.EPS


## Narrow phase, ring: the ball's centre stays within ring radius - r of the centre.
## Called only when it is past that. A bounce then leaves the ball the ring's least
## horizontal speed (as a pin does). On the drain arc a bounce counts toward draining, and
## so does time spent rolling there.
## A ball riding the ring (up the launch rail: about one ring contact a step) slides, and
## that answer is respond()'s written out here, two calls fewer a contact;
## tests/unit/test_ring_slide.gd pins it to respond() bit for bit.
func _touch_ring() -> void:
	var d: Vector2 = _p - _ring_center
	var dist: float = sqrt(d.length_squared())
	var nrm: Vector2 = -d / dist
	_p = _ring_center + d * (_ring_lim / dist)
	var bounced := false
	var vn: float = _v.dot(nrm)
	if vn < 0.0:
		var id: int = ContactId.RING
		var held: bool = id == _held_a or id == _held_b or id == _cur_a or id == _cur_b
		var gn_dt: float = _gravity.dot(nrm) * _dt
		if held or not ContactRule.bounces(vn, gn_dt, _threshold):
			var vt: Vector2 = _v - nrm * vn
			if _ring_lim > EPS:
				var t2: float = vt.length_squared()
				if t2 > EPS:
					var c: float = maxf(
						minf(vn - minf(gn_dt, 0.0), 0.0), -1.5 * t2 * (_h / _ring_lim)
					)
					vt *= sqrt((t2 + c * c) / t2)
			_v = vt
			if _cur_a == ContactId.NONE or _cur_a == id:
				_cur_a = id
				_n_a = nrm
			else:
				_cur_b = id
				_n_b = nrm
		else:
			bounced = respond(id, _ring_center, d, nrm, _ring_lim, Surface.RING, 0)
	# Only a bounce (the chapter's ring hit): a ball riding the ring up or down the rail
	# must be free to stop and roll back, which a kept sideways speed would forbid.
	if bounced and absf(_v.x) < _ring_min_speed_x:
		_v.x = _ring_min_speed_x if _v.x >= 0.0 else -_ring_min_speed_x
	if _has_drain_arc and _g.drained(d, bounced, _i, _h, _drain_hits, _drain_time):
		_queue(BallEvents.Kind.DRAINED, 0, 0.0)
		_gone = true


## Narrow phase, pins: the ball overlaps pin list entry `k` (offset `d` from its centre,
## contact distance `lim`). A capturing pin removes the ball; after touching any other, the
## ball keeps the pin's minimum horizontal speed.
func _touch_pin(k: int, d: Vector2, lim: float) -> void:
	var pin: int = _pin_items[k]
	if _pin_captures[pin] != 0:
		_queue(BallEvents.Kind.CAPTURED, _pin_tag[pin], 0.0)
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


## Narrow phase, capsule walls of the cell the ball is in now (the pins may have moved
## it): the deepest contact first, then again (up to three times). At a joint the flat side
## of one wall is deeper than the neighbour's cap, so the cap never adds a ghost bump. The
## search and the common answer are written out here, not called: most moving balls of a
## maze touch a wall, and roll along it (a held contact, or one too slow to bounce: the
## slide of respond(), line for line). A bounce or a glancing cap goes to respond().
## `cell` is the ball's cell when the caller knows it (-1 when a pin has just moved it).
func _touch_walls(cell: int) -> void:
	if cell < 0:
		var at: Vector2i = Vector2i((_p - _origin) * _inv_cell).clamp(Vector2i.ZERO, _last_cell)
		cell = at.y * _cols + at.x
	var k0: int = _wall_start[cell]
	var k1: int = _wall_start[cell + 1]
	for _pass: int in 3:
		var best := -1
		var found := 0
		var best_depth := 0.0
		var best_s := 0.0
		var best_q := Vector2.ZERO
		for k: int in range(k0, k1):
			var a: Vector2 = _wall_item_a[k]
			var ab: Vector2 = _wall_item_ab[k]
			var s: float = clampf((_p - a).dot(ab) * _wall_item_inv[k], 0.0, 1.0)
			var q: Vector2 = a + ab * s
			var reach: float = _wall_item_rad[k] + _r
			var d2: float = _p.distance_squared_to(q)
			if d2 < reach * reach:
				found += 1
				var depth: float = reach - sqrt(d2)
				if best < 0 or depth > best_depth:
					best = k
					best_depth = depth
					best_s = s
					best_q = q
		if best < 0:
			return
		# The deepest contact: how far from the ball, and which way it pushes.
		var lim: float = _wall_item_rad[best] + _r
		var wall: int = _wall_items[best]
		var d: Vector2 = _p - best_q
		var dist2: float = d.length_squared()
		var nrm := Vector2(0.0, -1.0)
		if dist2 > EPS * EPS:
			nrm = d / sqrt(dist2)
		elif _wall_inv_len2[wall] > 0.0:
			nrm = Vector2(_wall_ab[wall].y, -_wall_ab[wall].x).normalized()
		var on_cap: bool = best_s <= 0.0 or best_s >= 1.0
		_p = best_q + nrm * lim
		var id: int = (wall << ContactId.KIND_BITS) | ContactId.KIND_WALL
		var vn: float = _v.dot(nrm)
		var held: bool = id == _held_a or id == _held_b or id == _cur_a or id == _cur_b
		var gn_dt: float = _gravity.dot(nrm) * _dt
		var slides: bool = vn < 0.0 and not (on_cap and _caps_glance)
		if slides and (held or not ContactRule.bounces(vn, gn_dt, _threshold)):
			var vt: Vector2 = _v - nrm * vn
			var t2: float = vt.length_squared()
			if on_cap and lim > EPS and t2 > EPS:
				var c: float = maxf(minf(vn - minf(gn_dt, 0.0), 0.0), -1.5 * t2 * (_h / lim))
				vt *= sqrt((t2 + c * c) / t2)
			_v = vt
			# _note_contact(), written out.
			if _cur_a == ContactId.NONE or _cur_a == id:
				_cur_a = id
				_n_a = nrm
			else:
				_cur_b = id
				_n_b = nrm
		elif vn < 0.0:  # (a ball moving away gets no answer: respond() returns at once)
			var surface: int = Surface.WALL_CAP if on_cap else Surface.WALL_SIDE
			respond(id, best_q, d, nrm, lim, surface, wall)
		if found == 1:
			return


## The one contact response, for every surface. The narrow phase has put the ball back on
## the surface (it was at `centre` + `d`, closer than the contact distance `lim`); `nrm`
## points to the free side. Only a ball moving into the surface is answered: a new contact
## faster than the bounce threshold bounces (restitution on the normal speed, tangent
## friction on the rest, with the normal at the moment of impact on a round surface) and
## queues a hit event; a persisting or gentle one slides (see below). Either
## way it is recorded as a contact (the ball's support). Returns true on a bounce. (Hits
## nobody listens to are not queued: see BallMoverState._hits_heard.)
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
	if not held and ContactRule.bounces(vn, gn_dt, _threshold):
		if surface < Surface.WALL_SIDE:
			var back: Vector2 = d - _v * ContactMath.back_off(d, _v, lim, _h, inside)
			if back.length_squared() > EPS:
				nrm = back.normalized() * side
			_p = centre + nrm * (lim * side)
			vn = minf(_v.dot(nrm), 0.0)
		var e: float = _wall_e if surface >= Surface.WALL_CAP else _pin_e
		_v = (_v - nrm * vn) * _keep_tangent - nrm * (vn * e)
		var kind: int = HIT_EVENT[surface]
		if _hits_heard[kind] != 0:
			_queue(kind, index, -vn)
		bounced = true
	else:
		# Slide: the normal speed goes, except the part that only comes from a round surface
		# curving under the moving ball (capped by the curvature, substep time / radius),
		# which turns into tangential speed: riding the ring or rolling round a cap loses
		# nothing, while a push from gravity or other balls never turns into speed.
		var vt: Vector2 = _v - nrm * vn
		if surface < Surface.WALL_SIDE and lim > EPS:
			var t2: float = vt.length_squared()
			if t2 > EPS:
				var c: float = maxf(minf(vn - minf(gn_dt, 0.0), 0.0), -1.5 * t2 * (_h / lim))
				vt *= sqrt((t2 + c * c) / t2)
		_v = vt
	_note_contact(id, nrm)
	return bounced


## A wall cap under CapContact.GLANCE: the ball keeps only its speed along the cap's
## tangent (no bounce, and no turning to follow the curve), so it stops dead head-on and
## otherwise leaves the cap along the tangent. A new contact faster than the bounce
## threshold still queues a hit. Returns true on such a hit.
func _glance(id: int, nrm: Vector2, vn: float, index: int) -> bool:
	var held: bool = id == _held_a or id == _held_b or id == _cur_a or id == _cur_b
	# The seed's glancing cap counts the whole approach, gravity's share too.
	var hit: bool = not held and ContactRule.bounces(vn, 0.0, _threshold)
	if hit and _hits_heard[BallEvents.Kind.WALL_HIT] != 0:
		_queue(BallEvents.Kind.WALL_HIT, index, -vn)
	_v -= nrm * vn
	# The seed puts the ball back on the cap where its whole move would have ended and then
	# moves it on by the kept speed: along a cap it goes twice its tangential speed. That is
	# what lets a ball rolled dead at a cap slide off it within the seed's 16 frames.
	_p += _v * _h
	_note_contact(id, nrm)
	return hit


## Records a contact of the ball being moved with `id` (normal `nrm`): its first contact
## this step, or its second (a third replaces the second).
func _note_contact(id: int, nrm: Vector2) -> void:
	if _cur_a == ContactId.NONE or _cur_a == id:
		_cur_a = id
		_n_a = nrm
	else:
		_cur_b = id
		_n_b = nrm


## Narrow phase, windmills: the blades of each reachable wheel at `t` s into the step. A
## wheel's nearest blade is the one closest in angle; after answering it, the next nearest
## may touch too (in the narrow wedge by the pin), so it is looked for once more. True
## when a blade moved the ball.
func _touch_wheels(t: float) -> bool:
	var touched := false
	var b: BladeReach = _blades
	for k: int in range(b.near_from, b.near_to):
		var m: int = b.near_list[k]
		var reach: float = b.reach[m] + _r
		if (_p - b.center[m]).length_squared() >= reach * reach:
			continue
		for _pass: int in 2:
			if _gone or not _touch_blade(m, t):
				break
			touched = true
	return touched


## The nearest blade of wheel `m` at `t` s into the step, answered if it touches the ball:
## the response runs in the blade's frame (the ball's speed less the blade's surface speed
## at the contact), so a moving blade throws the ball; it keeps the blades' least
## horizontal speed and is held to the top speed; a free wheel gets the opposite angular
## impulse (queued, added up after the step).
func _touch_blade(m: int, t: float) -> bool:
	var b: BladeReach = _blades
	if not b.contact(m, t, _p, _r):
		return false
	var before: Vector2 = _v
	var surface_v: Vector2 = b.surface_v
	var surface: int = Surface.BLADE_SIDE if b.on_side else Surface.BLADE_CAP
	_p = b.axis + b.nrm * b.lim
	_v -= surface_v
	respond(b.id, b.axis, b.d, b.nrm, b.lim, surface, m)
	_v += surface_v
	var min_speed_x: float = b.min_speed_x[m]
	if absf(_v.x) < min_speed_x:
		_v.x = min_speed_x if _v.x >= 0.0 else -min_speed_x
	var speed2: float = _v.length_squared()
	if speed2 > _max_speed * _max_speed:
		_v *= _max_speed / sqrt(speed2)
	if b.free[m] != 0:
		var dv: Vector2 = _v - before
		var rim: Vector2 = b.rim
		var spin: float = (rim.y * dv.x - rim.x * dv.y) * b.inv_inertia[m]
		if spin != 0.0:
			wheel_push_index.append(m)
			wheel_push.append(spin)
	return true
