extends RefCounted
## The GDScript floor: the least work any step in GDScript must do per ball, timed on the
## real positions of a bench scene. It moves each ball by its velocity, keeps it in the ring,
## finds its grid cell, tests it against every pin and wall listed there, bins it, sorts the
## bins natively and tests every ball pair in neighbouring cells; it answers no contact
## (no bounce, no slide, no push, no sleep, no event). Its rate over GodotPhysics2D's rate
## is the most any GDScript layer built on a grid could reach against it on that scene, so
## a speed target above it cannot be met by tuning BallWorld.
##
## The states come from BallWorld running the scene (a snapshot every SNAPSHOT_EVERY steps):
## the kernel starts each of its steps from one, so it sees the contacts a real run sees.

const OursRunner := preload("res://tests/bench/physics/ours_runner.gd")
const CpuClock := preload("res://tests/bench/physics/cpu_clock.gd")
const BenchScenes := preload("res://tests/bench/physics/bench_scenes.gd")

const SNAPSHOT_EVERY := 4
## Kernel steps timed: enough for about half a second of CPU on the 10 ms clock.
const MIN_BALL_STEPS := 500000
const SORT_SHIFT := 21

var _pos: Array[PackedVector2Array] = []
var _vel: Array[PackedVector2Array] = []
var _scene: Dictionary
var _origin := Vector2.ZERO
var _inv := 1.0
var _cols := 1
var _rows := 1
var _pin_start := PackedInt32Array()
var _pin_pos := PackedVector2Array()
var _wall_start := PackedInt32Array()
var _wall_a := PackedVector2Array()
var _wall_ab := PackedVector2Array()
var _wall_inv := PackedFloat32Array()


func _init(scene: Dictionary) -> void:
	_scene = scene


## Runs the scene on BallWorld for `steps` steps to collect its states, and bins the
## scene's shapes. Call once, before time_round().
func prepare(steps: int) -> void:
	_record(steps)
	_bin()


## Times the kernel over the recorded states (about MIN_BALL_STEPS ball-steps). Returns
## {"floor_steps_per_s", "ns_per_ball_step", "overlaps_per_ball_step", "pairs_share"}
## (pairs_share: the share of the time the ball-pair part took).
## It writes nothing of the kernel's: two threads may run one kernel at once (its rates are
## then the process's CPU over both; MachineScaling.pair_scaling times such a pair by wall).
func time_round() -> Dictionary:
	var n: int = _pos[0].size()
	var rounds: int = maxi(1, ceili(float(MIN_BALL_STEPS) / (n * _pos.size())))
	var overlaps := 0
	# Wall-clock microseconds spent in the ball-pair part, for its share of the floor.
	var pairs_usec := 0
	var cpu0: int = CpuClock.usec()
	var wall0: int = Time.get_ticks_usec()
	for _r: int in rounds:
		for s: int in _pos.size():
			var step: Vector2i = _kernel_step(_pos[s].duplicate(), _vel[s].duplicate())
			overlaps += step.x
			pairs_usec += step.y
	var cpu: float = maxf((CpuClock.usec() - cpu0) / 1e6, 1e-6)
	var wall: int = maxi(Time.get_ticks_usec() - wall0, 1)
	var ball_steps: int = rounds * _pos.size() * n
	return {
		"floor_steps_per_s": ball_steps / cpu,
		"ns_per_ball_step": cpu * 1e9 / ball_steps,
		"overlaps_per_ball_step": float(overlaps) / ball_steps,
		"pairs_share": float(pairs_usec) / wall,
	}


func _record(steps: int) -> void:
	var w := OursRunner.build_world(_scene)
	var side := OursRunner.OursSide.new(w)
	var rng := RandomNumberGenerator.new()
	rng.seed = OursRunner.RULES_SEED
	var hz: float = _scene["hz"]
	for s: int in steps:
		w.step(1.0 / hz)
		if OursRunner.rules_due(_scene["mode"], s + 1):
			OursRunner.harness_rules(_scene["mode"], s + 1, w.get_positions(), rng, side, hz)
		if s >= OursRunner.WARMUP and s % SNAPSHOT_EVERY == 0:
			_pos.append(w.get_positions())
			_vel.append(w.get_velocities())


## Pins and walls into a uniform grid of one ball diameter (+1 px), each listed in every
## cell its shape grown by the ball radius (+1 px) touches, as BallWorld's grid does.
func _bin() -> void:
	var ball_r: float = _scene["ball_r"]
	var cell: float = 2.0 * ball_r + 1.0
	_inv = 1.0 / cell
	var box := Rect2(
		-BenchScenes.RING_R, -BenchScenes.RING_R, 2.0 * BenchScenes.RING_R, 2.0 * BenchScenes.RING_R
	)
	if not _scene["ring"]:
		box = Rect2()
	for p: Vector2 in _scene["pins"] + _scene["walls"]:
		box = box.expand(p)
	box = box.grow(2.0 * cell)
	_origin = box.position
	_cols = int(ceil(box.size.x * _inv))
	_rows = int(ceil(box.size.y * _inv))
	var pin_lists: Array[PackedVector2Array] = []
	pin_lists.resize(_cols * _rows)
	var grow: float = _scene["pin_r"] + ball_r + 1.0
	for p: Vector2 in _scene["pins"]:
		for c: int in _cells_of(p - Vector2(grow, grow), p + Vector2(grow, grow)):
			pin_lists[c].append(p)
	var wall_lists: Array[PackedInt32Array] = []
	wall_lists.resize(_cols * _rows)
	var walls: PackedVector2Array = _scene["walls"]
	grow = _scene["wall_r"] + ball_r + 1.0
	for k: int in walls.size() / 2:
		var a: Vector2 = walls[2 * k]
		var b: Vector2 = walls[2 * k + 1]
		var lo: Vector2 = a.min(b) - Vector2(grow, grow)
		for c: int in _cells_of(lo, a.max(b) + Vector2(grow, grow)):
			wall_lists[c].append(k)
	for c: int in _cols * _rows:
		_pin_start.append(_pin_pos.size())
		_pin_pos.append_array(pin_lists[c])
		_wall_start.append(_wall_a.size())
		for k: int in wall_lists[c]:
			var ab: Vector2 = walls[2 * k + 1] - walls[2 * k]
			_wall_a.append(walls[2 * k])
			_wall_ab.append(ab)
			_wall_inv.append(1.0 / ab.length_squared() if ab != Vector2.ZERO else 0.0)
	_pin_start.append(_pin_pos.size())
	_wall_start.append(_wall_a.size())


func _cells_of(lo: Vector2, hi: Vector2) -> PackedInt32Array:
	var out := PackedInt32Array()
	var c0 := Vector2i((lo - _origin) * _inv).clamp(Vector2i.ZERO, Vector2i(_cols - 1, _rows - 1))
	var c1 := Vector2i((hi - _origin) * _inv).clamp(Vector2i.ZERO, Vector2i(_cols - 1, _rows - 1))
	for y: int in range(c0.y, c1.y + 1):
		for x: int in range(c0.x, c1.x + 1):
			out.append(y * _cols + x)
	return out


## One step's least work over every ball; returns the overlaps it found (pins, walls, balls)
## and the microseconds its ball-pair part took.
func _kernel_step(pos: PackedVector2Array, vel: PackedVector2Array) -> Vector2i:
	var dt: float = 1.0 / float(_scene["hz"])
	var r: float = _scene["ball_r"]
	var pin_lim2: float = (r + _scene["pin_r"]) ** 2
	var wall_lim2: float = (r + _scene["wall_r"]) ** 2
	var ring_lim: float = BenchScenes.RING_R - r
	var ring_lim2: float = ring_lim * ring_lim if _scene["ring"] else INF
	# Locals, not members, in the loop: a member read costs more than a local one.
	var origin: Vector2 = _origin
	var inv: float = _inv
	var cols: int = _cols
	var last_cell := Vector2i(_cols - 1, _rows - 1)
	var pin_start: PackedInt32Array = _pin_start
	var pin_pos: PackedVector2Array = _pin_pos
	var wall_start: PackedInt32Array = _wall_start
	var wall_a: PackedVector2Array = _wall_a
	var wall_ab: PackedVector2Array = _wall_ab
	var wall_inv: PackedFloat32Array = _wall_inv
	var n: int = pos.size()
	var keys := PackedInt64Array()
	keys.resize(n + 1)
	var found := 0
	vel = Transform2D(Vector2.RIGHT, Vector2.DOWN, Vector2(0.0, 980.0) * dt) * vel
	for i: int in n:
		var p: Vector2 = pos[i] + vel[i] * dt
		var d2: float = p.length_squared()
		if d2 > ring_lim2:
			p *= ring_lim / sqrt(d2)
		var ci := Vector2i((p - origin) * inv).clamp(Vector2i.ZERO, last_cell)
		var c: int = ci.y * cols + ci.x
		for k: int in range(pin_start[c], pin_start[c + 1]):
			if (p - pin_pos[k]).length_squared() < pin_lim2:
				found += 1
		for k: int in range(wall_start[c], wall_start[c + 1]):
			var a: Vector2 = wall_a[k]
			var ab: Vector2 = wall_ab[k]
			var q: Vector2 = a + ab * clampf((p - a).dot(ab) * wall_inv[k], 0.0, 1.0)
			if (p - q).length_squared() < wall_lim2:
				found += 1
		pos[i] = p
		keys[i] = (c << SORT_SHIFT) | i
	keys[n] = 0x7fffffffffffffff
	keys.sort()
	var t0: int = Time.get_ticks_usec()
	found += _pairs(pos, keys, 4.0 * r * r)
	return Vector2i(found, Time.get_ticks_usec() - t0)


## Ball pairs closer than a diameter, over each ball's cell, the next and the three below.
func _pairs(pos: PackedVector2Array, keys: PackedInt64Array, lim2: float) -> int:
	var mask: int = (1 << SORT_SHIFT) - 1
	var next_off: int = 2 << SORT_SHIFT
	var below_off: int = (_cols - 1) << SORT_SHIFT
	var past_off: int = (_cols + 2) << SORT_SHIFT
	var cell_bits: int = ~mask
	var below := 0
	var found := 0
	for k: int in pos.size():
		# Each run ends at the first key past it; the sentinel ends the last.
		var key: int = keys[k]
		var cell_key: int = key & cell_bits
		var p: Vector2 = pos[key & mask]
		var end: int = cell_key + next_off
		var m: int = k + 1
		while keys[m] < end:
			if (pos[keys[m] & mask] - p).length_squared() < lim2:
				found += 1
			m += 1
		var first_below: int = cell_key + below_off
		while keys[below] < first_below:
			below += 1
		end = cell_key + past_off
		m = below
		while keys[m] < end:
			if (pos[keys[m] & mask] - p).length_squared() < lim2:
				found += 1
			m += 1
	return found
