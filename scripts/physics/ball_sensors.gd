class_name BallSensors
extends RefCounted
## The sensor pass of a BallWorld step, for one ball that just moved from `p_start` to `p`:
## holes, goals and zones. Internal to scripts/physics; the motion stage (BallMover) calls
## it only when the world has sensors, so boards without them pay nothing.


## True when a ball now at `p` with zone bits `mask` (set for the zones it was in) has
## crossed a zone's edge: only then has sense() work on a board with zones alone.
static func crossed_zone_edge(
	p: Vector2, mask: int, zone_pos: PackedVector2Array, zone_rad: PackedFloat32Array
) -> bool:
	for k: int in zone_pos.size():
		var zr: float = zone_rad[k]
		if (p.distance_squared_to(zone_pos[k]) <= zr * zr) != ((mask & (1 << k)) != 0):
			return true
	return false


## Queues the ball's sensor events in `ev` / `evs` and updates its goal and zone masks.
## Returns true when it fell in a hole (its centre came within the hole radius anywhere
## along the step's path): the caller removes it, and goals and zones are not looked at.
static func sense(
	g: StaticShapes,
	i: int,
	id: int,
	p_start: Vector2,
	p: Vector2,
	goal_mask: PackedInt32Array,
	zone_mask: PackedInt32Array,
	ev: PackedInt32Array,
	evs: PackedFloat32Array
) -> bool:
	for k: int in g.hole_pos.size():
		var hp: Vector2 = g.hole_pos[k]
		var q: Vector2 = Geometry2D.get_closest_point_to_segment(hp, p_start, p)
		var hr: float = g.hole_radius[k]
		if q.distance_squared_to(hp) <= hr * hr:
			_queue(ev, evs, BallEvents.Kind.HOLE, id, k)
			return true
	var n_goals: int = g.goal_pos.size()
	if n_goals > 0:
		goal_mask[i] = _crossings(g.goal_pos, g.goal_radius, goal_mask[i], p, id, ev, evs, true)
	if g.zone_pos.size() > 0:
		zone_mask[i] = _crossings(g.zone_pos, g.zone_radius, zone_mask[i], p, id, ev, evs, false)
	return false


## The new inside-bit mask for circles `pos` / `rad`: each bit that flips queues an enter
## event (GOAL or ZONE), and for goals a leave event too.
static func _crossings(
	pos: PackedVector2Array,
	rad: PackedFloat32Array,
	mask: int,
	p: Vector2,
	id: int,
	ev: PackedInt32Array,
	evs: PackedFloat32Array,
	goals: bool
) -> int:
	for k: int in pos.size():
		var r: float = rad[k]
		var inside: bool = p.distance_squared_to(pos[k]) <= r * r
		var bit: int = 1 << k
		if inside == ((mask & bit) != 0):
			continue
		mask ^= bit
		if goals:
			_queue(ev, evs, BallEvents.Kind.GOAL if inside else BallEvents.Kind.GOAL_LEFT, id, k)
		elif inside:
			_queue(ev, evs, BallEvents.Kind.ZONE, id, k)
	return mask


static func _queue(
	ev: PackedInt32Array, evs: PackedFloat32Array, kind: int, id: int, index: int
) -> void:
	ev.append(kind)
	ev.append(id)
	ev.append(index)
	evs.append(0.0)
