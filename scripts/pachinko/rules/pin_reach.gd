class_name PinReach
extends RefCounted
## Which field pins each launch power touches: one lone ball per STEP of power, launched as
## the rules launch it (LaunchRail's start and direction, the board's LaunchTable) into one
## world of the board with ball contacts off, followed until a pocket, the gutter or the
## rail's return takes it (or MAX_SECONDS pass). Gold pins are chosen from what some power
## reaches (gold_pins.gd), and the chasing pilot aims with it. Measured once per board
## shape and cached (the first game on a board pays about a second).

## Powers apart of two measured shots.
const STEP := 1.0
## Longest a shot is followed, seconds of game time.
const MAX_SECONDS := 12.0

static var _cache: Dictionary[String, PinReach] = {}

## Per measured power (index = power / STEP): the field pins the shot touched, in order.
var hits: Array[PackedInt32Array] = []
## Per measured power: the world pocket id that caught the lone shot, or -1 (the gutter,
## the rail's return, or still in the field at the end).
var ends := PackedInt32Array()

var _level: BoardLevel


## The reach of `level` (a pachinko board), measured once per board shape. Call it on one
## thread: the cache is not locked.
static func of(level: BoardLevel) -> PinReach:
	var key := _key(level)
	if not _cache.has(key):
		_cache[key] = _measure(level)
	return _cache[key]


## The field pins a shot of `power` (0..100) touches.
func pins_at(power: float) -> PackedInt32Array:
	if hits.is_empty():
		return PackedInt32Array()
	return hits[clampi(roundi(clampf(power, 0.0, 100.0) / STEP), 0, hits.size() - 1)]


## What a lone shot of `power` (0..100) is paid by its pocket (bonus pockets as they
## pay shut).
func payout_at(power: float) -> int:
	return _pocket_payout(_level, end_at(power))


## The board measured.
func board() -> BoardLevel:
	return _level


## The world pocket id that catches a lone shot of `power` (0..100), or -1.
func end_at(power: float) -> int:
	if ends.is_empty():
		return -1
	return ends[clampi(roundi(clampf(power, 0.0, 100.0) / STEP), 0, ends.size() - 1)]


## The powers (0..100, every STEP) whose shot touches pin `pin`.
func powers_reaching(pin: int) -> PackedFloat32Array:
	var out := PackedFloat32Array()
	for k in hits.size():
		if hits[k].has(pin):
			out.append(k * STEP)
	return out


## Every field pin some power touches, in pin order.
func reached_pins() -> PackedInt32Array:
	var seen: Dictionary[int, bool] = {}
	for shot in hits:
		for pin in shot:
			seen[pin] = true
	var out := PackedInt32Array(seen.keys())
	out.sort()
	return out


static func _measure(level: BoardLevel) -> PinReach:
	var reach := PinReach.new()
	var launch := LaunchCalibration.table(level)
	var world := BoardWorldFactory.build(level)
	world.threads = 1
	world.ball_contacts = false
	var start := LaunchRail.launch_position(level)
	var direction := LaunchRail.launch_direction(level)
	var count := int(100.0 / STEP) + 1
	# per power: pin → true, in the order touched (a Dictionary keeps its insertion order)
	var touched: Array[Dictionary] = []
	var power_of: Dictionary[int, int] = {}
	for k in count:
		touched.append({})
		var id := world.spawn_ball(
			start, direction * launch.launch_speed(k * STEP), level.ball_radius
		)
		if id >= 0:
			power_of[id] = k
	var field := _field_pins(level)
	var on_pin := func(ball: int, pin: int, _speed: float) -> void:
		if power_of.has(ball) and field.has(pin):
			touched[power_of[ball]][pin] = true
	world.pin_hit.connect(on_pin)
	var returned: Array[int] = []
	var on_zone := func(ball: int, _zone: int) -> void: returned.append(ball)
	world.ball_entered_zone.connect(on_zone)
	reach._level = level
	reach.ends.resize(count)
	reach.ends.fill(-1)
	var on_catch := func(ball: int, pocket: int) -> void:
		if power_of.has(ball):
			reach.ends[power_of[ball]] = pocket
	world.ball_captured.connect(on_catch)
	var dt := 1.0 / maxf(world.tuning.fixed_hz, 1.0)
	for step in int(MAX_SECONDS / dt):
		if world.ball_count() == 0:
			break
		world.step(dt)
		if not returned.is_empty():
			world.remove_balls(PackedInt32Array(returned))
			returned.clear()
	world.pin_hit.disconnect(on_pin)
	world.ball_entered_zone.disconnect(on_zone)
	world.ball_captured.disconnect(on_catch)
	for k in count:
		reach.hits.append(PackedInt32Array(touched[k].keys()))
	return reach


# The board's own pins that stand in the field (a pocket's pins are its walls, not targets).
static func _field_pins(level: BoardLevel) -> Dictionary[int, bool]:
	var out: Dictionary[int, bool] = {}
	for i in level.pins.size():
		if i >= level.pin_pocket.size() or level.pin_pocket[i] < 0:
			out[i] = true
	return out


static func _pocket_payout(level: BoardLevel, pocket: int) -> int:
	if level == null:
		return 0
	if pocket >= 0 and pocket < level.pockets.size():
		return maxi(level.pockets[pocket].payout, 0)
	var index := BonusGeometry.bonus_index(level, pocket)
	return maxi(level.bonus_pockets[index].payout, 0) if index >= 0 else 0


static func _key(level: BoardLevel) -> String:
	var shape := [level.board_id, level.pins, level.pockets.size(), level.windmills.size()]
	shape.append_array([level.rail_start_deg, level.rail_end_deg, level.ring_radius])
	return str(hash(shape), "/", level.bonus_pockets.size())
