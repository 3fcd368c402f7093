extends RefCounted
## The motion phase of a BallWorld step: each ball moves by its velocity plus its ball-ball
## separation, in substeps, against the ring, the pins and the capsule walls of its grid
## cell; then the sensors (holes, goals, zones) look at the path it took. Internal.
##
## One function on purpose: a GDScript call costs about as much as a contact test, so the
## per-ball work stays in one flat loop with the geometry inline. A bounce is written out
## where it happens: restitution on the normal, tangential friction on the rest,
## v' = (v - n·vn)·keep_t - n·(vn·e).

const BallStore := preload("res://scripts/physics/ball_store.gd")
const StaticGeometry := preload("res://scripts/physics/static_geometry.gd")
const BallStep := preload("res://scripts/physics/ball_step.gd")
const BallSensors := preload("res://scripts/physics/ball_sensors.gd")

const NO_CONTACT := 0
const RING_KEY := BallStep.RING_KEY
const EPS := BallStep.EPS


## Moves every awake ball one step of `dt` seconds and queues its events in b.events, with
## per-axis rolling `friction` (px/s²) and the speed cap applied first. Sleepers were
## settled by BallSleep.settle() and are skipped. No ball falls asleep while `may_sleep` is
## false (within sleep_time of a wake-up).
static func move(
	b: BallStore,
	g: StaticGeometry,
	t: PhysicsTuning,
	gravity: Vector2,
	friction: Vector2,
	dt: float,
	may_sleep: bool
) -> void:
	var n: int = b.ids.size()
	var pos: PackedVector2Array = b.pos
	var vel: PackedVector2Array = b.vel
	var rad: PackedFloat32Array = b.radius
	var push: PackedVector2Array = b.push
	var ids: PackedInt32Array = b.ids
	var asleep: PackedByteArray = b.asleep
	var sup_ball: PackedVector2Array = b.support_ball
	var support: PackedVector2Array = b.support_static
	var support2: PackedVector2Array = b.support_static2
	var tracing: bool = b.tracing
	var trace_ball: PackedInt32Array = b.trace_ball
	var trace_pos: PackedVector2Array = b.trace_pos
	var ca: PackedInt32Array = b.contact_a
	var cb: PackedInt32Array = b.contact_b
	var rest: PackedFloat32Array = b.rest
	var ghits: PackedInt32Array = b.gutter_hits
	var gtime: PackedFloat32Array = b.gutter_time
	var gmask: PackedInt32Array = b.goal_mask
	var zmask: PackedInt32Array = b.zone_mask
	var ev: PackedInt32Array = b.events
	var evs: PackedFloat32Array = b.event_speed

	var pin_pos: PackedVector2Array = g.pin_pos
	var pin_rad: PackedFloat32Array = g.pin_radius
	var pin_special: PackedByteArray = g.pin_special
	var pin_pocket: PackedInt32Array = g.pin_pocket
	var pin_start: PackedInt32Array = g.pin_start
	var zoned: bool = g.zoned
	var pin_items: PackedInt32Array = g.pin_items if zoned else g.all_pins
	var item_pos: PackedVector2Array = g.pin_item_pos if zoned else pin_pos
	var item_rad: PackedFloat32Array = g.pin_item_radius if zoned else pin_rad
	var n_pins: int = pin_pos.size()
	var wall_ab: PackedVector2Array = g.wall_ab
	var wall_inv: PackedFloat32Array = g.wall_inv_len2
	var wall_start: PackedInt32Array = g.wall_start
	var wall_items: PackedInt32Array = g.wall_items
	var wall_item_a: PackedVector2Array = g.wall_item_a
	var wall_item_ab: PackedVector2Array = g.wall_item_ab
	var wall_item_inv: PackedFloat32Array = g.wall_item_inv
	var wall_item_rad: PackedFloat32Array = g.wall_item_radius
	var origin: Vector2 = g.origin
	var inv: float = g.inv_cell
	var cols: int = g.cols
	var rows: int = g.rows
	# Cell lookups in one Vector2i conversion and clamp: half the VM work of two clampi().
	var last_cell := Vector2i(cols - 1, rows - 1)
	var has_ring: bool = g.has_ring
	var rc: Vector2 = g.ring_center
	var ring_r: float = g.ring_radius
	var has_gutter: bool = g.has_gutter
	var has_sensors: bool = g.hole_pos.size() > 0 or g.goal_pos.size() > 0 or g.zone_pos.size() > 0

	var pin_e: float = t.restitution
	var wall_e: float = t.wall_restitution
	var keep_t: float = t.tangent_friction
	var thr: float = t.bounce_threshold
	var min_h: float = t.min_horizontal_speed
	var rest2: float = t.rest_speed * t.rest_speed
	var sleep_time: float = t.sleep_time if may_sleep else 0.0
	var max_speed: float = t.max_speed
	# Friction per axis as one clamp: v - clamp(v, -f, f) slows each axis by up to f and
	# never past zero.
	var fr: Vector2 = friction.max(Vector2.ZERO) * dt
	var has_friction: bool = fr != Vector2.ZERO
	var cap2: float = max_speed * max_speed
	# A ball pushed apart by more than a resting ball moves in a step is still settling.
	var settled_push: float = t.rest_speed * dt
	var slide_time: float = t.gutter_slide_time
	var travel_share: float = BallStep.TRAVEL_SHARE
	var max_substeps: int = BallStep.MAX_SUBSTEPS
	var has_walls: bool = g.wall_a.size() > 0
	var last_r := -1.0
	var max_travel := 0.0
	var max_travel2 := 0.0
	var ring_lim := 0.0
	var ring_lim2 := 0.0

	for i: int in n:
		if asleep[i] != 0:
			continue  # BallSleep.settle() already held it still for this step
		var p: Vector2 = pos[i]
		var p_start: Vector2 = p
		var v: Vector2 = vel[i]
		if has_friction:
			v -= v.clamp(-fr, fr)
		var sp2: float = v.length_squared()
		if sp2 > cap2:
			v *= max_speed / sqrt(sp2)
		var r: float = rad[i]
		var pu: Vector2 = push[i]
		var pu_len := 0.0
		if pu != Vector2.ZERO:
			pu_len = pu.length()
			if pu_len > 0.5 * r:
				pu *= 0.5 * r / pu_len
				pu_len = 0.5 * r
		var cur_a: int = NO_CONTACT
		var cur_b: int = NO_CONTACT
		# Normals of those two contacts: the ball's support (see BallStore).
		var n_a := Vector2.ZERO
		var n_b := Vector2.ZERO
		if r != last_r:
			last_r = r
			max_travel = g.max_travel(r, travel_share)
			max_travel2 = max_travel * max_travel
			ring_lim = maxf(ring_r - r, 0.0)
			ring_lim2 = ring_lim * ring_lim
		var mv: Vector2 = v * dt + pu
		var steps := 1
		var h: float = dt
		var pu_step: Vector2 = pu
		if mv.length_squared() > max_travel2 or pu_len > 0.0:
			var travel: float = mv.length() + pu_len
			if travel > max_travel:
				steps = mini(int(ceil(travel / max_travel)), max_substeps)
				h = dt / steps
				pu_step = pu / steps
		var gone := false
		for sub: int in steps:
			if tracing and sub > 0:
				trace_ball.append(i)
				trace_pos.append(p)
			p += v * h + pu_step
			# Ring: the ball's centre stays within ring_r - r of the centre.
			if has_ring:
				var d: Vector2 = p - rc
				var d2: float = d.length_squared()
				if d2 > ring_lim2:
					var lim: float = ring_lim
					var dist: float = sqrt(d2)
					var nrm: Vector2 = -d / dist
					p = rc + d * (lim / dist)
					var vn: float = v.dot(nrm)
					var in_gutter: bool = has_gutter and g.in_gutter(d)
					if vn < 0.0:
						var key: int = RING_KEY
						var held: bool = (
							key == ca[i] or key == cb[i] or key == cur_a or key == cur_b
						)
						var gn_dt: float = gravity.dot(nrm) * dt
						if not held and minf(gn_dt, 0.0) - vn > thr:
							var back: Vector2 = d - v * BallStep.back_off(d, v, lim, h, true)
							if back.length_squared() > EPS:
								nrm = -back.normalized()
							p = rc - nrm * lim
							vn = minf(v.dot(nrm), 0.0)
							v = (v - nrm * vn) * keep_t - nrm * (vn * pin_e)
							ev.append(BallStep.Ev.RING_HIT)
							ev.append(ids[i])
							ev.append(0)
							evs.append(-vn)
							if in_gutter:
								ghits[i] += 1
						else:
							var curv: float = h / lim if lim > EPS else 0.0
							v = BallStep.slide(v, nrm, vn, gn_dt, curv)
						if cur_a == NO_CONTACT or cur_a == key:
							cur_a = key
							n_a = nrm
						else:
							cur_b = key
							n_b = nrm
					if in_gutter:
						gtime[i] += h
						if ghits[i] >= g.gutter_bounces or gtime[i] >= slide_time:
							ev.append(BallStep.Ev.DRAINED)
							ev.append(ids[i])
							ev.append(0)
							evs.append(0.0)
							gone = true
							break
			var ci: Vector2i = Vector2i((p - origin) * inv).clamp(Vector2i.ZERO, last_cell)
			var c: int = ci.y * cols + ci.x
			var pin_touched := false
			var k0 := 0
			var k1: int = n_pins
			if zoned:
				k0 = pin_start[c]
				k1 = pin_start[c + 1]
			for k: int in range(k0, k1):
				var q: Vector2 = item_pos[k]
				var d: Vector2 = p - q
				var lim: float = item_rad[k] + r
				var d2: float = d.length_squared()
				if d2 >= lim * lim:
					continue
				pin_touched = true
				var pid: int = pin_items[k]
				if pin_special[pid] != 0:
					ev.append(BallStep.Ev.POCKETED)
					ev.append(ids[i])
					ev.append(pin_pocket[pid])
					evs.append(0.0)
					gone = true
					break
				var dist: float = sqrt(d2)
				var nrm := Vector2(0.0, -1.0)
				if dist > EPS:
					nrm = d / dist
				p = q + nrm * lim
				var vn: float = v.dot(nrm)
				if vn < 0.0:
					var key: int = pid + 1
					var held: bool = key == ca[i] or key == cb[i] or key == cur_a or key == cur_b
					var gn_dt: float = gravity.dot(nrm) * dt
					if not held and minf(gn_dt, 0.0) - vn > thr:
						var back: Vector2 = d - v * BallStep.back_off(d, v, lim, h, false)
						if back.length_squared() > EPS:
							nrm = back.normalized()
						p = q + nrm * lim
						vn = minf(v.dot(nrm), 0.0)
						v = (v - nrm * vn) * keep_t - nrm * (vn * pin_e)
						ev.append(BallStep.Ev.PIN_HIT)
						ev.append(ids[i])
						ev.append(pid)
						evs.append(-vn)
					else:
						v = BallStep.slide(v, nrm, vn, gn_dt, h / lim)
					if cur_a == NO_CONTACT or cur_a == key:
						cur_a = key
						n_a = nrm
					else:
						cur_b = key
						n_b = nrm
				if min_h > 0.0 and absf(v.x) < min_h:
					v.x = min_h if v.x >= 0.0 else -min_h
			if gone:
				break
			if not has_walls:
				continue
			if pin_touched:
				ci = Vector2i((p - origin) * inv).clamp(Vector2i.ZERO, last_cell)
				c = ci.y * cols + ci.x
			# Deepest contact first, then again: at a joint the flat side of one wall is
			# deeper than the neighbour's cap, so the cap never adds a ghost bump.
			for _pass: int in 3:
				var found := 0
				var best := -1
				var best_d2 := 0.0
				var best_lim := 0.0
				var best_depth := 0.0
				var best_s := 0.0
				var best_q := Vector2.ZERO
				for k: int in range(wall_start[c], wall_start[c + 1]):
					var a: Vector2 = wall_item_a[k]
					var ab: Vector2 = wall_item_ab[k]
					var s: float = clampf((p - a).dot(ab) * wall_item_inv[k], 0.0, 1.0)
					var q: Vector2 = a + ab * s
					var d: Vector2 = p - q
					var lim: float = wall_item_rad[k] + r
					var d2: float = d.length_squared()
					if d2 >= lim * lim:
						continue
					var depth: float = lim - sqrt(d2)
					found += 1
					if depth > best_depth or best < 0:
						best = wall_items[k]
						best_depth = depth
						best_d2 = d2
						best_lim = lim
						best_s = s
						best_q = q
				if best < 0:
					break
				var d: Vector2 = p - best_q
				var lim: float = best_lim
				var nrm := Vector2(0.0, -1.0)
				if best_d2 > EPS * EPS:
					nrm = d / sqrt(best_d2)
				elif wall_inv[best] > 0.0:
					var ab: Vector2 = wall_ab[best]
					nrm = Vector2(ab.y, -ab.x).normalized()
				p = best_q + nrm * lim
				var vn: float = v.dot(nrm)
				if vn < 0.0:
					var key: int = -(best + 1)
					var held: bool = key == ca[i] or key == cb[i] or key == cur_a or key == cur_b
					var gn_dt: float = gravity.dot(nrm) * dt
					var on_cap: bool = best_s <= 0.0 or best_s >= 1.0
					if not held and minf(gn_dt, 0.0) - vn > thr:
						if on_cap:
							var back: Vector2 = d - v * BallStep.back_off(d, v, lim, h, false)
							if back.length_squared() > EPS:
								nrm = back.normalized()
							p = best_q + nrm * lim
							vn = minf(v.dot(nrm), 0.0)
						v = (v - nrm * vn) * keep_t - nrm * (vn * wall_e)
						ev.append(BallStep.Ev.WALL_HIT)
						ev.append(ids[i])
						ev.append(best)
						evs.append(-vn)
					else:
						# Only the round caps curve; on a flat side a slide only drops vn.
						if on_cap:
							v = BallStep.slide(v, nrm, vn, gn_dt, h / lim)
						else:
							v -= nrm * vn
					if cur_a == NO_CONTACT or cur_a == key:
						cur_a = key
						n_a = nrm
					else:
						cur_b = key
						n_b = nrm
				if found == 1:
					break
		# A ball touching nothing now or last step has nothing to update: it saves writes
		# for most of a flowing board.
		if cur_a != NO_CONTACT or ca[i] != NO_CONTACT:
			ca[i] = cur_a
			cb[i] = cur_b
			support[i] = n_a
			support2[i] = n_b
		pos[i] = p
		vel[i] = v
		if gone:
			b.kill(i)
			continue
		if v.length_squared() < rest2:
			var rested: float = rest[i] + dt
			rest[i] = rested
			# A ball lying in the gutter never sleeps: it must still drain.
			if (
				sleep_time > 0.0
				and rested >= sleep_time
				and pu_len < settled_push
				and gtime[i] == 0.0
				and ghits[i] == 0
			):
				var on_ball: Vector2 = sup_ball[i]
				var on_static: bool = on_ball == Vector2.ZERO
				asleep[i] = BallStore.SLEEP_HELD if on_static else BallStore.SLEEP_ON_BALLS
				b.sleep_ball_normal[i] = on_ball
				vel[i] = Vector2.ZERO
		else:
			rest[i] = 0.0
		if has_sensors and BallSensors.sense(g, i, ids[i], p_start, p, gmask, zmask, ev, evs):
			b.kill(i)

	b.pos = pos
	b.vel = vel
	b.asleep = asleep
	b.support_static2 = support2
	b.support_static = support
	b.trace_ball = trace_ball
	b.trace_pos = trace_pos
	b.contact_a = ca
	b.contact_b = cb
	b.rest = rest
	b.gutter_hits = ghits
	b.gutter_time = gtime
	b.goal_mask = gmask
	b.zone_mask = zmask
	b.events = ev
	b.event_speed = evs
