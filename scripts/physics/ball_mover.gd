extends "res://scripts/physics/ball_narrow_phase.gd"
## The motion stage for one lane of balls: each awake ball moves by its velocity plus its
## ball-ball separation, in substeps short enough that no ball can cross a pin, a wall or
## the ring; each substep runs the narrow phase per shape kind (ring, pins, walls), and
## every contact goes through one response, respond(); near a windmill the blades come
## last (_touch_wheels, in the blade's moving frame): see BallNarrowPhase. Then its rest time,
## sleep and sensors. Internal to scripts/physics: BallWorld has one mover per lane.
##
## A mover reads the last state and writes only the slots of the balls it moves, plus its
## own event and path buffers, which the world merges in lane order; so the result is the
## same for any number of lanes. The ball being moved lives in members (_p, _v, ...) while
## it moves: a GDScript call costs about as much as a contact test, so calls happen per
## substep and per contact, and the per-candidate tests are written out inside the loops.

const BallSensors := preload("res://scripts/physics/ball_sensors.gd")
const BallPairs := preload("res://scripts/physics/ball_pairs.gd")
const BallSleep := preload("res://scripts/physics/ball_sleep.gd")

## Safety bound on substeps for one ball in one step.
const MAX_SUBSTEPS := 1024


## Moves the awake balls in slots from..to, one at a time in members: friction and the speed
## cap (SpeedRules.limit(), written out), then substeps (each: move, then the narrow phase
## per shape kind), then its contacts, position and broad-phase key; then, still there, its
## rest time or sleep and its sensor pass (_after_move). Written out as one loop with the
## pin tests and the write-back inline: a GDScript call costs about as much as a contact
## test, and calls on two threads run no faster than on one (see LaneCrew), so calls happen
## per contact and for rarer rules. What needs no call:
## - most balls need one substep and have no push;
## - a ball no pin moved is still in the cell it was keyed to, and an empty wall cell is
##   passed over;
## - a ball touching nothing now or last step keeps its contact slots as they are (that
##   saves writes for most of a flowing board);
## - a ball with no push and no windmill about gets its substep count here, and a moving
##   ball on a board with zones alone (every pachinko board) its zone-edge test: those two
##   calls, and the one to _after_move(), were a quarter of a contact-free world's step;
## - the broad phase's key for next step (see BallStore.cell_keys) is rewritten only when
##   the ball left its cell (found by its old key in BallStore.sorted_keys), and not at all
##   when the keys are stale anyway (no broad phase ran: it bins every ball again before it
##   reads them). The keys lie in cell order, so every lane's balls share cache lines in
##   them, and a write there stalls the other core (about 50 µs a step of S1 on two
##   threads when every key was written).
func move_range(from: int, to: int) -> void:
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
		_v -= _v.clamp(-_fr_zero, _fr_zero)
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
		elif (_v * _dt).length_squared() > _max_travel * _max_travel:
			steps = mini(ceili((_v * _dt).length() / _max_travel), MAX_SUBSTEPS)
		_h = _dt / steps
		_p_start = _p
		var c := 0  # the ball's cell (its key), while no contact has moved it
		var at := Vector2i.ZERO
		var cell_stale := true
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
				var k0: int = _pin_start[c] if _zoned else 0
				var k1: int = _pin_start[c + 1] if _zoned else _pin_items.size()
				for k: int in range(k0, k1):
					var d: Vector2 = _p - _pin_item_pos[k]
					var lim: float = _pin_item_rad[k] + _r
					if d.length_squared() < lim * lim and not _gone:
						_touch_pin(k, d, lim)
						moved = true
			cell_stale = moved
			if _has_walls and not _gone and (moved or _wall_start[c] != _wall_start[c + 1]):
				_touch_walls(c if not moved else -1)
				cell_stale = true
			if _near_wheel and not _gone and _touch_wheels((sub + 1) * _h):
				cell_stale = true
			if _gone:
				break
		if _cur_a != ContactId.NONE or _held_a != ContactId.NONE:
			_write_contacts(i)
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
		elif _v.length_squared() < _rest_speed2 or (_has_sensors and not _zones_only):
			_after_move(i)
		else:
			_rest[i] = 0.0
			if _has_sensors:
				for k: int in _zone_pos.size():
					var zr: float = _zone_rad[k]
					var inside: bool = _p.distance_squared_to(_zone_pos[k]) <= zr * zr
					if inside != ((_zone_mask[i] & (1 << k)) != 0):
						_sense(i)
						break


## Stores the ball's contacts of this step and their normals (its supports next step),
## then clears them for the next ball. Only a ball touching something now or last step
## comes here: the others keep their contact slots as they are.
func _write_contacts(i: int) -> void:
	_contact_a[i] = _cur_a
	_contact_b[i] = _cur_b
	_support_static[i] = _n_a
	_support_static2[i] = _n_b
	_cur_a = ContactId.NONE
	_cur_b = ContactId.NONE
	_n_a = Vector2.ZERO
	_n_b = Vector2.ZERO


## Ball `i` left its cell for cell `c`: its broad-phase key is rewritten where the broad
## phase sorted it (found in BallStore.sorted_keys by the cell it was keyed with). Only
## such balls are rekeyed: see move_range().
func _rekey(i: int, c: int) -> void:
	var slot: int = _sorted_keys.bsearch((_key_cell[i] << BallPairs.SORT_SHIFT) | i)
	_cell_keys[slot] = (c << BallPairs.SORT_SHIFT) | i
	_key_cell[i] = c


## Ball `i` after its move: its rest time or sleep (BallSleep.sleep_if_settled), then its sensor
## pass. With zones alone (no holes, no goals) BallSensors has work only when the ball
## crossed a zone's edge, so that is looked for first.
func _after_move(i: int) -> void:
	if _v.length_squared() >= _rest_speed2:
		_rest[i] = 0.0
	else:
		# It rests `dt` longer; once it has rested the sleep time it may fall asleep. Near a
		# windmill a ball never sleeps: a sleeper does not move, and a blade would pass it.
		var rested: float = _rest[i] + _dt
		_rest[i] = rested
		if not _near_wheel and _sleep_time > 0.0 and rested >= _sleep_time:
			BallSleep.sleep_if_settled(_store, i, _settled_push)
	if not _has_sensors:
		return
	if _zones_only and not BallSensors.crossed_zone_edge(_p, _zone_mask[i], _zone_pos, _zone_rad):
		return
	_sense(i)


## Ball `i`'s sensor pass (BallSensors.sense): a ball that fell in a hole leaves the world.
func _sense(i: int) -> void:
	if BallSensors.sense(_g, i, _ids[i], _p_start, _p, _goal_mask, _zone_mask, events, event_speed):
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
