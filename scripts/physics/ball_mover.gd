class_name BallMover
extends RefCounted
## The motion kernel: one lane of the motion stage, from a ball's velocity to its sensors.
## For each awake ball of its lane: friction and the speed cap, then substeps short enough
## that no ball can cross a pin, a wall or the ring, each running the narrow phase per
## shape kind (ring, pins, capsule walls, and near a windmill its blades, in the blade's
## moving frame) with every contact answered by the one response, respond(); then the
## ball's contacts, position and broad-phase key, its rest time or sleep and its sensors.
## Internal to scripts/physics: BallWorld has one mover per lane (MotionStage runs them).
##
## A kernel (docs/architecture.md, "Kernels"): one long file, written out on purpose, and
## exempt from the physics files' length limits. The step's ball arrays, geometry and
## constants and the ball being moved are typed members of this one object (begin() copies
## them in): a member read is one indexed read where another object's field is a hash
## lookup, and a GDScript call costs about as much as a contact test, so calls happen per
## substep and per contact and the per-candidate tests are written out inside the loops.
## Every written-out copy of a readable rule here is pinned to that rule bit for bit by a
## test (scripts/physics/README.md lists them).
##
## A mover reads the last state and writes only the slots of the balls it moves, plus its
## own event and path buffers, which the world merges in lane order; so the result is the
## same for any number of lanes.

## Shapes as respond() sees them: the ring holds the ball inside; pins and wall and blade
## caps are round; the flat sides (from WALL_SIDE on) do not curve. Blades bounce like walls.
enum Surface { RING, PIN, WALL_CAP, BLADE_CAP, WALL_SIDE, BLADE_SIDE }

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
	BallEvents.Kind.BLADE_HIT,
	BallEvents.Kind.WALL_HIT,
	BallEvents.Kind.BLADE_HIT
]
## Distances below this count as zero (px).
const EPS := ContactMath.EPS

## This lane's events of the step, in order (see BallEvents), and its path points.
var events := PackedInt32Array()
var event_speed := PackedFloat32Array()
var trace_ball := PackedInt32Array()
var trace_pos := PackedVector2Array()
## This lane's pushes on free windmills, in ball order: wheel index and change of its
## angular speed (rad/s); the world adds them up after the step (Windmills.advance).
var wheel_push_index := PackedInt32Array()
var wheel_push := PackedFloat64Array()
## False has move_range() call _touch_walls() where it otherwise runs its written-out copy
## (tests/unit/test_wall_search_copy.gd runs both and compares them bit for bit).
var walls_written_out := true

# The step's inputs, copied in by begin(): ball arrays (this lane writes its own slots
# only), static geometry (read only) and constants. Members rather than reads through the
# store and geometry objects: a member is one indexed read, a named read a hash lookup.
# The ball arrays are the BallFields.TABLE rows this class declares as `_name` (see
# _take_balls()).
var _pos := PackedVector2Array()
var _vel := PackedVector2Array()
var _radius := PackedFloat32Array()
var _push := PackedVector2Array()
var _ids := PackedInt32Array()
var _alive := PackedByteArray()
var _asleep := PackedByteArray()
var _rest := PackedFloat32Array()
var _contact_a := PackedInt32Array()
var _contact_b := PackedInt32Array()
var _support_static := PackedVector2Array()
var _support_static2 := PackedVector2Array()
var _support_ball := PackedVector2Array()
var _sleep_ball_normal := PackedVector2Array()
var _drain_hits := PackedInt32Array()
var _drain_time := PackedFloat32Array()
var _goal_mask := PackedInt32Array()
var _zone_mask := PackedInt32Array()
var _cell_keys := PackedInt64Array()
var _key_cell := PackedInt32Array()
## This step's sorted keys (BallStore.sorted_keys): read only.
var _sorted_keys := PackedInt64Array()
## The store itself, for the rarer per-ball work that reads it by name (BallSleep.sleep_if_settled).
var _store: BallStore
## 1 for each hit event kind (BallEvents.Kind.PIN_HIT, WALL_HIT, RING_HIT, BLADE_HIT) some signal
## handler listens to: the others are not queued (on a busy board most events are hits).
var _hits_heard := PackedByteArray([1, 1, 1, 1])
## False when the store's broad-phase keys are stale this step: then none are written.
var _keyed := true
## The grid (max_travel) and the shapes it bins (the ring's radius, the drain arc, sensors).
var _g: StaticGeometry
var _shapes: StaticShapes
var _zoned := true
## False on a board without pins (a maze): the mover then skips the pin test outright.
var _has_pins := true
## Entries of _pin_items (every pin's, when the grid does not zone them).
var _pin_count := 0
var _pin_start := PackedInt32Array()
var _pin_items := PackedInt32Array()
var _pin_item_pos := PackedVector2Array()
var _pin_item_rad := PackedFloat32Array()
var _pin_captures := PackedByteArray()
var _pin_tag := PackedInt32Array()
var _pin_min_speed_x := PackedFloat64Array()
var _wall_start := PackedInt32Array()
# The capsule walls of each grid cell: entries _wall_start[c] .. _wall_start[c + 1] of the
# _wall_item_* lists (the wall's index, its end a, a to b, 1 / |ab|², radius); the walls'
# own a to b and 1 / |ab|² by wall index. Copied as members: the narrow phase reads them
# per substep, and a member is one indexed read where another object's field is a lookup.
var _has_walls := false
var _wall_items := PackedInt32Array()
var _wall_item_a := PackedVector2Array()
var _wall_item_ab := PackedVector2Array()
var _wall_item_inv := PackedFloat32Array()
var _wall_item_rad := PackedFloat32Array()
var _wall_ab := PackedVector2Array()
var _wall_inv_len2 := PackedFloat32Array()
var _has_ring := false
var _ring_center := Vector2.ZERO
var _ring_min_speed_x := 0.0
var _has_drain_arc := false
var _has_sensors := false
## True when the sensors are zones alone (no holes, no goals): the mover then looks for a
## zone edge crossed before it calls BallSensors.
var _zones_only := false
## True when every moved ball gets the sensor pass (holes or goals on the board).
var _sense_every_ball := false
var _zone_pos := PackedVector2Array()
var _zone_rad := PackedFloat32Array()
## The windmills as this lane sees them (see BladeReach), and whether the ball being moved
## can reach one this step (then it substeps for the blades and never falls asleep).
var _blades := BladeReach.new()
var _near_wheel := false
## True on a board with windmills (the substep count then looks for them).
var _has_wheels := false
var _origin := Vector2.ZERO
var _inv_cell := 1.0
var _cols := 1
var _last_cell := Vector2i.ZERO
var _gravity := Vector2.ZERO
var _dt := 0.0
var _max_speed := 0.0
## This step's rolling friction and speed cap (applied once per moving ball).
var _speed := SpeedRules.new()
# Its numbers, as members (see SpeedRules: move_range() applies them per ball without a call).
var _fr_shift := Vector2.ZERO
var _fr_zero := Vector2.ZERO
var _cap_per_axis := false
var _cap_low := Vector2.ZERO
var _cap_high := Vector2.ZERO
var _cap2 := 0.0
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
## Set when the ball left the world this substep (captured by a pin or drained).
var _gone := false
## Where the ball being moved started this step (for the sensors' path test).
var _p_start := Vector2.ZERO
# Per-radius limits, cached while consecutive balls share a radius.
var _max_travel := 0.0
var _max_travel2 := 0.0
var _ring_lim := 0.0
var _ring_lim2 := 0.0


## Takes this step's state and constants and clears the lane's buffers. Called on the
## world's thread before the lanes run; `may_sleep` is false just after a wake-up;
## `hits_heard` has 1 for each hit event kind to queue (see _hits_heard).
func begin(
	b: BallStore,
	g: StaticGeometry,
	wheels: Windmills,
	t: PhysicsTuning,
	gravity: Vector2,
	friction: Vector2,
	dt: float,
	may_sleep: bool,
	hits_heard: PackedByteArray
) -> void:
	_hits_heard = hits_heard
	_take_balls(b)
	_take_geometry(g)
	_blades.take(wheels)
	_has_wheels = _blades.has_wheels
	_near_wheel = false
	_gravity = gravity
	_dt = dt
	_max_speed = t.max_speed
	_speed.prepare(t, gravity, friction.max(Vector2.ZERO) * dt, dt)
	_fr_shift = _speed.shift
	_fr_zero = _speed.toward_zero
	_cap_per_axis = _speed.per_axis
	_cap_low = _speed.low
	_cap_high = _speed.high
	_cap2 = _speed.cap * _speed.cap
	_caps_glance = t.wall_cap_contact == PhysicsTuning.CapContact.GLANCE
	_pin_e = t.restitution
	_wall_e = t.wall_restitution
	_keep_tangent = t.tangent_friction
	_threshold = t.bounce_threshold
	_rest_speed2 = t.rest_speed * t.rest_speed
	_sleep_time = t.sleep_time if may_sleep else 0.0
	_settled_push = t.rest_speed * dt
	_tracing = b.tracing
	_r = -1.0
	_cur_a = ContactId.NONE
	_cur_b = ContactId.NONE
	_n_a = Vector2.ZERO
	_n_b = Vector2.ZERO
	events.resize(0)
	event_speed.resize(0)
	trace_ball.resize(0)
	trace_pos.resize(0)
	wheel_push_index.resize(0)
	wheel_push.resize(0)


# BallFields.take(b, self) written out: a named set and get per row cost about 6 µs a
# step (in the editor, where the member names are made on each call, more), and each
# analysis world steps thousands of times. tests/unit/test_ball_fields.gd pins it to take().
func _take_balls(b: BallStore) -> void:
	_store = b
	_pos = b.pos
	_vel = b.vel
	_radius = b.radius
	_ids = b.ids
	_alive = b.alive
	_rest = b.rest
	_asleep = b.asleep
	_drain_hits = b.drain_hits
	_drain_time = b.drain_time
	_goal_mask = b.goal_mask
	_zone_mask = b.zone_mask
	_contact_a = b.contact_a
	_contact_b = b.contact_b
	_support_static = b.support_static
	_support_static2 = b.support_static2
	_support_ball = b.support_ball
	_sleep_ball_normal = b.sleep_ball_normal
	_push = b.push
	_cell_keys = b.cell_keys
	_key_cell = b.key_cell
	_keyed = b.keys_valid
	_sorted_keys = b.sorted_keys


func _take_geometry(g: StaticGeometry) -> void:
	_g = g
	_shapes = g.shapes
	var s: StaticShapes = g.shapes
	_zoned = g.zoned
	_pin_start = g.pin_start
	_pin_items = g.pin_items if g.zoned else g.all_pins
	_pin_item_pos = g.pin_item_pos if g.zoned else s.pin_pos
	_pin_item_rad = g.pin_item_radius if g.zoned else s.pin_radius
	_pin_captures = s.pin_captures
	_pin_tag = s.pin_tag
	_pin_min_speed_x = s.pin_min_speed_x
	_has_pins = not _pin_items.is_empty()
	_pin_count = _pin_items.size()
	_has_walls = not s.wall_a.is_empty()
	_wall_start = g.wall_start
	_wall_items = g.wall_items
	_wall_item_a = g.wall_item_a
	_wall_item_ab = g.wall_item_ab
	_wall_item_inv = g.wall_item_inv
	_wall_item_rad = g.wall_item_radius
	_wall_ab = s.wall_ab
	_wall_inv_len2 = s.wall_inv_len2
	_has_ring = s.has_ring
	_ring_center = s.ring_center
	_ring_min_speed_x = s.ring_min_speed_x
	_has_drain_arc = s.has_drain_arc
	_has_sensors = not (s.hole_pos.is_empty() and s.goal_pos.is_empty() and s.zone_pos.is_empty())
	_zones_only = s.hole_pos.is_empty() and s.goal_pos.is_empty()
	_sense_every_ball = _has_sensors and not _zones_only
	_zone_pos = s.zone_pos
	_zone_rad = s.zone_radius
	_origin = g.origin
	_inv_cell = g.inv_cell
	_cols = g.cols
	_last_cell = Vector2i(g.cols - 1, g.rows - 1)


## The limits that depend on the ball radius (kept while consecutive balls share one).
func _set_radius(r: float) -> void:
	_r = r
	_max_travel = _g.max_travel(r, TRAVEL_SHARE)
	_max_travel2 = _max_travel * _max_travel
	_ring_lim = maxf(_shapes.ring_radius - r, 0.0)
	_ring_lim2 = _ring_lim * _ring_lim


## Records where ball `i` is between two substeps (the swept check's path; see
## BallStore.tracing).
func _trace(i: int) -> void:
	trace_ball.append(i)
	trace_pos.append(_p)


## Queues an event of `kind` for the ball being moved (see BallEvents).
func _queue(kind: int, index: int, speed: float) -> void:
	events.append(kind)
	events.append(_ids[_i])
	events.append(index)
	event_speed.append(speed)


# The motion: the loop over the lane's balls and its helpers.


## Moves the awake balls in slots from..to, one at a time in members: friction and the speed
## cap (SpeedRules.limit(), written out: tests/unit/test_speed_limit_copy.gd pins it), then
## substeps (each: move, then the narrow phase per shape kind), then its contacts, position
## and broad-phase key; then, still there, its rest time or sleep and its sensor pass.
## Written out as one loop with the pin tests and the write-back inline: a GDScript call
## costs about as much as a contact test, and calls on two threads run no faster than on
## one (see LaneCrew), so calls happen per contact and for rarer rules.
## What needs no call:
## - most balls need one substep and have no push;
## - a ball no pin moved is still in the cell it was keyed to, and an empty wall cell is
##   passed over;
## - the wall search of a ball no pin moved (_touch_walls(), written out here with its
##   commonest answer, a held contact sliding on a flat side, first and the wall's id,
##   held test and gravity's share computed only for a ball moving into the wall): a call
##   per substep, with its locals set up and torn down, was about a fifth of a maze
##   ball's motion (tests/unit/test_wall_search_copy.gd pins the copy to _touch_walls());
## - a ball's contacts and supports are stored in the loop (a call less per touching ball);
## - a ball touching nothing now or last step keeps its contact slots as they are (that
##   saves writes for most of a flowing board);
## - a ball with no push and no windmill about gets its substep count here, and a moving
##   ball on a board with zones alone (every pachinko board) its zone-edge test: those two
##   calls, and one to the rest-and-sensors step, were a quarter of a contact-free world's step
##   (tests/unit/test_mover_inline_copies.gd pins both copies to _substeps() and
##   BallSensors.crossed_zone_edge());
## - the broad phase's key for next step (see BallStore.cell_keys) is rewritten only when
##   the ball left its cell (found by its old key in BallStore.sorted_keys), and not at all
##   when the keys are stale anyway (no broad phase ran: it bins every ball again before it
##   reads them). The keys lie in cell order, so every lane's balls share cache lines in
##   them, and a write there stalls the other core (about 50 µs a step of S1 on two
##   threads when every key was written).
func move_range(from: int, to: int) -> void:
	var fr_low: Vector2 = -_fr_zero
	# Per ball (declared once: each ball's first substep sets all three before they are read):
	# its cell (its key) while no contact has moved it, and whether a contact may have.
	var c := 0
	var at := Vector2i.ZERO
	var cell_stale := true
	for i: int in range(from, to):
		if _asleep[i] != 0:
			continue
		_i = i
		_p = _pos[i]
		_v = _vel[i]
		_gone = false
		_held_a = _contact_a[i]
		_held_b = _contact_b[i]
		_v -= _fr_shift
		_v -= _v.clamp(fr_low, _fr_zero)
		if _cap_per_axis:
			_v = _v.clamp(_cap_low, _cap_high)
		elif _v.length_squared() > _cap2:
			_v *= _max_speed / sqrt(_v.length_squared())
		if _radius[i] != _r:
			_set_radius(_radius[i])
		_push_step = _push[i]
		var steps := 1
		if _push_step != Vector2.ZERO or _has_wheels:
			steps = _substeps(_push_step)
		elif (_v * _dt).length_squared() > _max_travel2:
			steps = mini(ceili((_v * _dt).length() / _max_travel), MAX_SUBSTEPS)
		_h = _dt / steps
		_p_start = _p
		for sub: int in steps:
			if _tracing and sub > 0:
				_trace(i)
			_p += _v * _h + _push_step
			if _has_ring and (_p - _ring_center).length_squared() > _ring_lim2:
				_touch_ring()
			at = Vector2i((_p - _origin) * _inv_cell).clamp(Vector2i.ZERO, _last_cell)
			c = at.y * _cols + at.x
			var moved := false
			if _has_pins:
				var k0 := 0
				var k1: int = _pin_count
				if _zoned:
					k0 = _pin_start[c]
					k1 = _pin_start[c + 1]
				for k: int in range(k0, k1):
					var d: Vector2 = _p - _pin_item_pos[k]
					var lim: float = _pin_item_rad[k] + _r
					if d.length_squared() < lim * lim and not _gone:
						_touch_pin(k, d, lim)
						moved = true
			cell_stale = moved
			if _has_walls and not _gone:
				if moved or not walls_written_out:
					_touch_walls(c if not moved else -1)
					cell_stale = true
				else:
					# _touch_walls(c), written out: see the note above this function.
					var k0: int = _wall_start[c]
					var k1: int = _wall_start[c + 1]
					for _pass: int in 3 if k0 != k1 else 0:
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
							break
						cell_stale = true
						var lim: float = _wall_item_rad[best] + _r
						var wall: int = _wall_items[best]
						var d: Vector2 = _p - best_q
						var dist2: float = d.length_squared()
						var nrm := Vector2(0.0, -1.0)
						if dist2 > EPS * EPS:
							nrm = d / sqrt(dist2)
						elif _wall_inv_len2[wall] > 0.0:
							nrm = Vector2(_wall_ab[wall].y, -_wall_ab[wall].x).normalized()
						_p = best_q + nrm * lim
						var vn: float = _v.dot(nrm)
						if vn < 0.0:  # (a ball moving away gets no answer)
							var on_cap: bool = best_s <= 0.0 or best_s >= 1.0
							var id: int = (wall << ContactId.KIND_BITS) | ContactId.KIND_WALL
							var held: bool = (
								id == _held_a or id == _held_b or id == _cur_a or id == _cur_b
							)
							if held and not on_cap:
								# The commonest answer: a held contact sliding on a flat side.
								_v -= nrm * vn
								if _cur_a == ContactId.NONE or _cur_a == id:
									_cur_a = id
									_n_a = nrm
								else:
									_cur_b = id
									_n_b = nrm
							elif on_cap and _caps_glance:
								respond(id, best_q, d, nrm, lim, Surface.WALL_CAP, wall)
							else:
								var gn_dt: float = _gravity.dot(nrm) * _dt
								if held or not ContactRule.bounces(vn, gn_dt, _threshold):
									var vt: Vector2 = _v - nrm * vn
									if on_cap and lim > EPS:
										var t2: float = vt.length_squared()
										if t2 > EPS:
											var cv: float = maxf(
												minf(vn - minf(gn_dt, 0.0), 0.0),
												-1.5 * t2 * (_h / lim)
											)
											vt *= sqrt((t2 + cv * cv) / t2)
									_v = vt
									if _cur_a == ContactId.NONE or _cur_a == id:
										_cur_a = id
										_n_a = nrm
									else:
										_cur_b = id
										_n_b = nrm
								else:
									var surface: int = (
										Surface.WALL_CAP if on_cap else Surface.WALL_SIDE
									)
									respond(id, best_q, d, nrm, lim, surface, wall)
						if found == 1:
							break
			if _near_wheel and not _gone and _touch_wheels((sub + 1) * _h):
				cell_stale = true
			if _gone:
				break
		if _cur_a != ContactId.NONE or _held_a != ContactId.NONE:
			# The ball's contacts of this step and their normals (its supports next step),
			# then cleared for the next ball. A ball touching nothing now or last step keeps
			# its contact slots as they are.
			_contact_a[i] = _cur_a
			_contact_b[i] = _cur_b
			_support_static[i] = _n_a
			_support_static2[i] = _n_b
			_cur_a = ContactId.NONE
			_cur_b = ContactId.NONE
			_n_a = Vector2.ZERO
			_n_b = Vector2.ZERO
		_pos[i] = _p
		_vel[i] = _v
		if _keyed:
			if cell_stale:
				at = Vector2i((_p - _origin) * _inv_cell).clamp(Vector2i.ZERO, _last_cell)
				c = at.y * _cols + at.x
			if _key_cell[i] != c:
				_rekey(i, c)
		if _gone:
			_alive[i] = 0
		elif _v.length_squared() < _rest_speed2:
			# It rests `dt` longer; once it has rested the sleep time it may fall asleep. Near
			# a windmill a ball never sleeps: a sleeper does not move, and a blade would pass
			# it. Then its sensor pass: with zones alone (no holes, no goals) BallSensors has
			# work only when the ball crossed a zone's edge, so that is looked for first.
			var rested: float = _rest[i] + _dt
			_rest[i] = rested
			if not _near_wheel and _sleep_time > 0.0 and rested >= _sleep_time:
				BallSleep.sleep_if_settled(_store, i, _settled_push)
			if (
				_has_sensors
				and (
					not _zones_only
					or BallSensors.crossed_zone_edge(_p, _zone_mask[i], _zone_pos, _zone_rad)
				)
			):
				_sense(i)
		elif _sense_every_ball:
			_rest[i] = 0.0
			_sense(i)
		else:
			_rest[i] = 0.0
			if _has_sensors:
				for k: int in _zone_pos.size():
					var zr: float = _zone_rad[k]
					var inside: bool = _p.distance_squared_to(_zone_pos[k]) <= zr * zr
					if inside != ((_zone_mask[i] & (1 << k)) != 0):
						_sense(i)
						break


## Ball `i` left its cell for cell `c`: its broad-phase key is rewritten where the broad
## phase sorted it (found in BallStore.sorted_keys by the cell it was keyed with). Only
## such balls are rekeyed: see move_range().
func _rekey(i: int, c: int) -> void:
	var slot: int = _sorted_keys.bsearch((_key_cell[i] << BallPairs.SORT_SHIFT) | i)
	_cell_keys[slot] = (c << BallPairs.SORT_SHIFT) | i
	_key_cell[i] = c


## Ball `i`'s sensor pass (BallSensors.sense): a ball that fell in a hole leaves the world.
func _sense(i: int) -> void:
	if BallSensors.sense(
		_shapes, i, _ids[i], _p_start, _p, _goal_mask, _zone_mask, events, event_speed
	):
		_alive[i] = 0


## Substeps of at most the safe travel: the velocity's plus the push's (ball-ball
## separation, capped at half the radius here), more near a windmill; sets the push share
## of each substep.
func _substeps(push: Vector2) -> int:
	var travel: float = (_v * _dt).length()
	if push != Vector2.ZERO:
		var push_len: float = push.length()
		if push_len > 0.5 * _r:
			push *= 0.5 * _r / push_len
			push_len = 0.5 * _r
		travel = (_v * _dt + push).length() + push_len
	var steps := 1
	if travel > _max_travel:
		steps = mini(ceili(travel / _max_travel), MAX_SUBSTEPS)
	_push_step = push / steps
	if _has_wheels:
		steps = _wheel_steps(steps)
	return steps


## The windmills the ball being moved can reach this step (see BladeReach.find_near), and
## the substeps it then needs: `steps`, or more near a wheel (BladeReach.substeps_near).
func _wheel_steps(steps: int) -> int:
	var push_len: float = _push_step.length() * steps
	var at: Vector2i = Vector2i((_p - _origin) * _inv_cell).clamp(Vector2i.ZERO, _last_cell)
	_blades.find_near(at.y * _cols + at.x, (_v * _dt).length() + push_len)
	var need: int = _blades.substeps_near(_r, _max_speed, _dt, push_len, _max_travel)
	_near_wheel = need > 0
	if need <= steps:
		return steps
	_push_step *= float(steps) / float(mini(need, MAX_SUBSTEPS))
	return mini(need, MAX_SUBSTEPS)


# The narrow phase, per shape kind, and the one contact response.


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
			# _note_contact(), written out (tests/unit/test_contact_record.gd pins it).
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
	if _has_drain_arc and _shapes.drained(d, bounced, _i, _h, _drain_hits, _drain_time):
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
## slide of respond(), line for line: tests/unit/test_wall_slide.gd pins it to respond() bit
## for bit). A bounce or a glancing cap goes to respond().
## `cell` is the ball's cell when the caller knows it (-1 when a pin has just moved it).
## move_range() calls this only for a ball a pin has just moved: for the others it runs its
## written-out copy (tests/unit/test_wall_search_copy.gd pins the two together).
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
			# _note_contact(), written out (tests/unit/test_contact_record.gd pins it).
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
## nobody listens to are not queued: see _hits_heard.)
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
