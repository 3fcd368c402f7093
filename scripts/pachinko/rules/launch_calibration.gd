extends RefCounted
## Measures, on the board's own world, the slowest launch that still clears the rail.
## Energy alone says sqrt(2·g·Δh), but riding the curved rail costs a little (contacts,
## the hop from the outer wall to the guide near the top), and that depends on the
## physics and the board. So the launcher asks the simulation itself: a binary search
## over single test shots, done once per board and cached.

## Test shots in the binary search (the range shrinks 256 times: under 1 px/s).
const ITERATIONS := 8
## Longest a test shot is followed, seconds.
const MAX_SECONDS := 4.0
## A little over the measured minimum, so a clearing shot never stalls at the top.
const SAFETY := 1.01

static var _cache: Dictionary[String, float] = {}


## The slowest launch speed (px/s) that carries a lone ball out of the rail of `level`.
static func clear_speed(level: BoardLevel) -> float:
	var key := _key(level)
	if _cache.has(key):
		return _cache[key]
	var tuning := BoardWorldFactory.tuning_for(level)
	var g := tuning.gravity.length()
	# The rail never meets a pin: test on the bare ring and rail, which builds much faster.
	var bare := level.duplicate() as BoardLevel
	bare.pins = PackedVector2Array()
	bare.pin_pocket = PackedInt32Array()
	bare.pin_special = PackedByteArray()
	var rise := LaunchRail.launch_position(level).y - LaunchRail.highest_lane_y(level)
	var ideal := sqrt(2.0 * g * maxf(rise, 0.0))
	var low := ideal * 0.95
	var high := ideal * 1.25 + 20.0
	if not _clears(bare, high):
		push_error("LaunchCalibration: no test shot clears the rail of '%s'" % level.board_id)
		_cache[key] = high
		return high
	for i in ITERATIONS:
		var mid := (low + high) * 0.5
		if _clears(bare, mid):
			high = mid
		else:
			low = mid
	var result := high * SAFETY
	_cache[key] = result
	return result


# True when a lone ball launched at `speed` leaves the rail past its end.
static func _clears(level: BoardLevel, speed: float) -> bool:
	var world := BoardWorldFactory.build(level)
	if world == null:
		return false
	var start := LaunchRail.launch_position(level)
	var id := world.spawn_ball(start, LaunchRail.launch_direction(level) * speed, level.ball_radius)
	var dt := 1.0 / maxf(world.tuning.fixed_hz, 1.0)
	var sweep := absf(level.rail_end_deg - level.rail_start_deg)
	var direction := -1.0 if level.rail_end_deg < level.rail_start_deg else 1.0
	var last_angle := rad_to_deg((start - level.ring_center).angle())
	var travelled := 0.0
	for i in int(MAX_SECONDS / dt):
		world.step(dt)
		if not world.has_ball(id):
			return false
		var angle := rad_to_deg((world.get_ball_position(id) - level.ring_center).angle())
		travelled += wrapf(angle - last_angle, -180.0, 180.0) * direction
		last_angle = angle
		if travelled > sweep + 2.0:
			return true
		if travelled < -5.0:
			return false
	return false


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
