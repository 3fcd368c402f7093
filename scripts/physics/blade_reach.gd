class_name BladeReach
extends RefCounted
## The windmills as one motion lane sees them during a step: their pose at the step's
## start (copied by take()), which wheels the ball being moved can reach (find_near()),
## and the geometry of its contact with a wheel's nearest blade (contact()). What a contact
## does to the ball is BallMover's (its _touch_blade): this part only finds it. Internal to
## scripts/physics; each BallMover has one.

## False on a board without windmills (then nothing here is read).
var has_wheels := false
## The wheels the ball being moved can reach this step: near_list[near_from .. near_to)
## (its cell's list, or every wheel).
var near_list := PackedInt32Array()
var near_from := 0
var near_to := 0
# The wheels (see Windmills), their pose at the step's start.
var center := PackedVector2Array()
var omega := PackedFloat64Array()
var free := PackedByteArray()
var inv_inertia := PackedFloat64Array()
var min_speed_x := PackedFloat64Array()
var reach := PackedFloat64Array()
# The contact contact() found: the closest point on the blade's axis, the normal (to the
# ball), contact distance, the ball's offset from `axis`, the blade rim point (from the
# pin) and its velocity, the contact id, and whether it is on the blade's flat side.
var axis := Vector2.ZERO
var nrm := Vector2.ZERO
var lim := 0.0
var d := Vector2.ZERO
var rim := Vector2.ZERO
var surface_v := Vector2.ZERO
var id := 0
var on_side := false

var _blades := PackedInt32Array()
var _length := PackedFloat64Array()
var _blade_r := PackedFloat64Array()
var _angle := PackedFloat64Array()
var _start := PackedInt32Array()
var _items := PackedInt32Array()
var _margin := 0.0
var _all := PackedInt32Array()


## Takes this step's wheels (their pose at its start).
func take(w: Windmills) -> void:
	has_wheels = w.count() > 0
	if not has_wheels:
		return
	center = w.center
	_blades = w.blades
	_length = w.length
	_blade_r = w.blade_radius
	reach = w.reach
	_angle = w.angle
	omega = w.omega
	free = w.free
	inv_inertia = w.inv_inertia
	min_speed_x = w.min_speed_x
	_start = w.start
	_items = w.items
	_margin = w.margin
	if _all.size() != w.count():
		_all.resize(w.count())
		for m: int in w.count():
			_all[m] = m


## Sets the near list for a ball at grid cell `cell` that may travel `travel` px this
## step: its cell's wheels, or every wheel when it may go past the binning margin.
func find_near(cell: int, travel: float) -> void:
	if travel > _margin:
		near_list = _all
		near_from = 0
		near_to = _all.size()
	else:
		near_list = _items
		near_from = _start[cell]
		near_to = _start[cell + 1]


## The substeps a ball of radius `r` needs near the wheels find_near() listed (0 when
## none): in a blade's turning frame it must move less than `max_travel` per substep even
## at the top speed `max_speed` (a blade may throw it so), with the fastest reachable
## blade's speed added, and its ball-ball push (`push_len` px) on top; then no blade and no
## ball pass through each other.
func substeps_near(
	r: float, max_speed: float, dt: float, push_len: float, max_travel: float
) -> int:
	if near_to <= near_from:
		return 0
	var fastest := 0.0
	for k: int in range(near_from, near_to):
		var m: int = near_list[k]
		fastest = maxf(fastest, absf(omega[m]) * (reach[m] + r))
	return ceili(((max_speed + fastest) * dt + push_len) / max_travel)


## True when wheel `m`'s nearest blade at `t` s into the step touches a ball of radius `r`
## at `p` (the one closest in angle); then the members above describe the contact.
func contact(m: int, t: float, p: Vector2, r: float) -> bool:
	var c: Vector2 = center[m]
	var q: Vector2 = p - c
	var n: int = _blades[m]
	var pitch: float = TAU / n
	var turn: float = _angle[m] + omega[m] * t
	var k: int = roundi((atan2(q.y, q.x) - turn) / pitch)
	var dir: Vector2 = Vector2.from_angle(turn + k * pitch)
	var blade_len: float = _length[m]
	var s: float = clampf(q.dot(dir), 0.0, blade_len)
	axis = c + dir * s
	d = p - axis
	lim = _blade_r[m] + r
	var d2: float = d.length_squared()
	if d2 >= lim * lim:
		return false
	nrm = Vector2(-dir.y, dir.x)
	if d2 > ContactMath.EPS * ContactMath.EPS:
		nrm = d / sqrt(d2)
	rim = axis + nrm * _blade_r[m] - c
	surface_v = Vector2(-rim.y, rim.x) * omega[m]
	var blade: int = posmod(k, n)
	id = ((m << ContactId.BLADE_BITS | blade) << ContactId.KIND_BITS) | ContactId.KIND_BLADE
	on_side = s > 0.0 and s < blade_len
	return true
