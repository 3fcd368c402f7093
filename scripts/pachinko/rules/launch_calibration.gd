class_name LaunchCalibration
extends RefCounted
## Measures a board's launch rail on its own world: first the slowest launch that still
## clears the rail (a binary search over single test shots), then a LaunchTable of launch
## speeds from there up and the speed each has at the rail's mouth. Energy alone would say
## sqrt(2·g·Δh) to clear, but riding the curved rail costs a little (contacts, the hop from
## the outer wall to the guide near the top), and that depends on the physics and the
## board, so the simulation itself is asked. Done once per board and cached.

## Test shots in the binary search (the range shrinks 2^12 times: well under 1 px/s).
const ITERATIONS := 12
## Longest a test shot is followed, seconds.
const MAX_SECONDS := 4.0
## A hair over the measured minimum, so the weakest shot never stalls at the top.
const SAFETY := 1.0005
## Launch speeds in the table: the slowest clearing one and this many steps above it.
const TABLE_STEPS := 48
## The table reaches this many times EXIT_SPEED_MAX's energy above the clearing launch
## (the climb loses some of it to friction).
const TABLE_HEADROOM := 2.0

static var _cache: Dictionary[String, LaunchTable] = {}


## The launch table of `level` (cached per board shape). Call it on one thread: the cache
## is not shared safely between threads; the table it returns is.
static func table(level: BoardLevel) -> LaunchTable:
	var key := _key(level)
	if _cache.has(key):
		return _cache[key]
	var result := _measure(level)
	_cache[key] = result
	return result


## The slowest launch speed (px/s) that carries a lone ball out of the rail of `level`.
static func clear_speed(level: BoardLevel) -> float:
	return table(level).bottom[0]


static func _measure(level: BoardLevel) -> LaunchTable:
	# The rail never meets a pin: test on the bare ring and rail, which builds much faster.
	var bare := level.duplicate() as BoardLevel
	bare.pins = PackedVector2Array()
	bare.pin_pocket = PackedInt32Array()
	bare.pin_special = PackedByteArray()
	bare.bonus_pockets = []
	var clear := _clear_speed(bare)
	var top := clear * clear + TABLE_HEADROOM * LaunchPower.EXIT_SPEED_MAX ** 2
	var speeds := PackedFloat64Array()
	for k in TABLE_STEPS + 1:
		speeds.append(sqrt(lerpf(clear * clear, top, float(k) / TABLE_STEPS)))
	var mouths := _mouth_speeds(bare, speeds)
	var result := LaunchTable.new()
	for k in speeds.size():
		# A launch that did not get out (not expected above the clearing one) is left out.
		if mouths[k] >= 0.0:
			result.add(speeds[k], mouths[k])
	if result.bottom.is_empty():
		result.add(clear, 0.0)
	return result


static func _clear_speed(bare: BoardLevel) -> float:
	var tuning := BoardWorldFactory.tuning_for(bare)
	var g := tuning.gravity.length()
	var rise := LaunchRail.launch_position(bare).y - LaunchRail.highest_lane_y(bare)
	var ideal := sqrt(2.0 * g * maxf(rise, 0.0))
	var low := ideal * 0.9
	var high := ideal * 1.3 + 20.0
	if _mouth_speeds(bare, PackedFloat64Array([high]))[0] < 0.0:
		push_error("LaunchCalibration: no test shot clears the rail of '%s'" % bare.board_id)
		return high
	for i in ITERATIONS:
		var mid := (low + high) * 0.5
		if _mouth_speeds(bare, PackedFloat64Array([mid]))[0] >= 0.0:
			high = mid
		else:
			low = mid
	return high * SAFETY


# Fires one ball per launch speed in `speeds` side by side (no ball contacts) and returns
# each one's speed as it passed the rail's mouth, or -1 for a ball that never got 2° past
# it (it rolled back).
static func _mouth_speeds(bare: BoardLevel, speeds: PackedFloat64Array) -> PackedFloat64Array:
	var result := PackedFloat64Array()
	result.resize(speeds.size())
	result.fill(-1.0)
	var world := BoardWorldFactory.build(bare)
	if world == null:
		return result
	world.threads = 1
	world.ball_contacts = false
	var start := LaunchRail.launch_position(bare)
	var direction := LaunchRail.launch_direction(bare)
	var ids := PackedInt32Array()
	for speed in speeds:
		ids.append(world.spawn_ball(start, direction * speed, bare.ball_radius))
	var dt := 1.0 / maxf(world.tuning.fixed_hz, 1.0)
	var sweep := absf(bare.rail_end_deg - bare.rail_start_deg)
	var sense := -1.0 if bare.rail_end_deg < bare.rail_start_deg else 1.0
	var start_angle := rad_to_deg((start - bare.ring_center).angle())
	var last_angle := PackedFloat64Array()
	var travelled := PackedFloat64Array()
	var passed := PackedFloat64Array()
	for k in speeds.size():
		last_angle.append(start_angle)
		travelled.append(0.0)
		passed.append(-1.0)
	var open := speeds.size()
	for i in int(MAX_SECONDS / dt):
		world.step(dt)
		for k in speeds.size():
			if result[k] >= 0.0 or not world.has_ball(ids[k]) or travelled[k] < -5.0:
				continue
			var p := world.get_ball_position(ids[k])
			var angle := rad_to_deg((p - bare.ring_center).angle())
			travelled[k] += wrapf(angle - last_angle[k], -180.0, 180.0) * sense
			last_angle[k] = angle
			if passed[k] < 0.0 and travelled[k] >= sweep:
				passed[k] = world.get_ball_velocity(ids[k]).length()
			if travelled[k] > sweep + 2.0:
				result[k] = passed[k]
				open -= 1
			elif travelled[k] < -5.0:
				open -= 1
		if open <= 0:
			break
	return result


static func _key(level: BoardLevel) -> String:
	return (
		"%d:%s:%s:%s:%s:%s:%s"
		% [
			level.get_instance_id(),
			level.ring_center,
			level.ring_radius,
			level.rail_width,
			level.rail_start_deg,
			level.rail_end_deg,
			level.ball_radius,
		]
	)
