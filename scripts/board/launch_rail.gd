class_name LaunchRail
extends RefCounted
## Geometry of a pachinko board's launch rail: the channel between the ring border and an
## inner guide arc. A ball fired from the bottom of the channel travels up it (through
## decreasing angles, so up the right side) and leaves it at `rail_end_deg` into the field.
## The channel's bottom is closed by a short stopper wall; a ball that rolls back down lands
## in the return zone (world zone 0) just above the stopper.

## Radius of the guide arc's capsules and of the stopper, in pixels.
const GUIDE_WALL_RADIUS := 2.0
## Largest angle between two guide points, degrees (keeps the capsule chain smooth).
const GUIDE_STEP_DEG := 3.0
## The deflector on the far side: a ramp leaving the ring DEFLECTOR_OUTER_DEG past the
## rail's end and reaching DEFLECTOR_DEPTH rail widths inside the ring DEFLECTOR_INNER_DEG
## past it. A ball leaves the rail in free flight and its speed decides how far across the
## top it carries (that is how power aims), so nothing may stand in that flight; past the
## farthest flight, a ball that meets the ring and rides it (a knock from another ball)
## slides off the ramp into the field instead of riding round into the gutter.
const DEFLECTOR_OUTER_DEG := 125.0
const DEFLECTOR_INNER_DEG := 140.0
const DEFLECTOR_DEPTH := 1.5
## Where the rail should open for power to aim (degrees): short of the top on the right, so a
## ball leaves heading up and left and its speed decides how far it carries.
const AIMING_END_DEG := -30.0
## The flight lane under the top of the ring, kept clear of free pins: within
## FLIGHT_LANE_DEPTH px of the ring between FLIGHT_LANE_FROM_DEG and FLIGHT_LANE_TO_DEG. A
## ball crosses it in free flight, so a strong shot lands farther from the rail than a weak
## one; with pins there every shot hits the same first pins and power stops aiming.
const FLIGHT_LANE_DEPTH := 80.0
const FLIGHT_LANE_FROM_DEG := -160.0
const FLIGHT_LANE_TO_DEG := -45.0


## Radius of the guide arc's centre line.
static func guide_radius(level: BoardLevel) -> float:
	return level.ring_radius - level.rail_width


## Radius along the middle of the channel, where a launched ball starts.
static func lane_radius(level: BoardLevel) -> float:
	return level.ring_radius - level.rail_width * 0.5 + GUIDE_WALL_RADIUS * 0.5


## The guide arc as points from the rail's start to its end (a chain of capsules).
static func guide_points(level: BoardLevel) -> PackedVector2Array:
	var sweep := absf(level.rail_end_deg - level.rail_start_deg)
	var count := maxi(2, ceili(sweep / GUIDE_STEP_DEG) + 1)
	return PinPatterns.arc(
		level.ring_center, guide_radius(level), level.rail_start_deg, level.rail_end_deg, count
	)


## The stopper closing the bottom of the channel: from the guide's first point out to the
## ring, as [a, b].
static func stopper(level: BoardLevel) -> PackedVector2Array:
	var direction := _unit(level.rail_start_deg)
	return PackedVector2Array(
		[
			level.ring_center + direction * guide_radius(level),
			level.ring_center + direction * level.ring_radius,
		]
	)


## Radius at which a ball rides the ring: touching it from inside.
static func riding_radius(level: BoardLevel) -> float:
	return level.ring_radius - level.ball_radius - 0.05


## The deflector wall past the rail's end, as [a on the ring, b inside the field].
static func deflector(level: BoardLevel) -> PackedVector2Array:
	var sense := _rail_sense(level)
	var outer := _unit(level.rail_end_deg + sense * DEFLECTOR_OUTER_DEG)
	var inner := _unit(level.rail_end_deg + sense * DEFLECTOR_INNER_DEG)
	return PackedVector2Array(
		[
			level.ring_center + outer * level.ring_radius,
			level.ring_center + inner * (level.ring_radius - level.rail_width * DEFLECTOR_DEPTH),
		]
	)


## Centre of the return zone: where a ball resting on the stopper sits (it lies against
## the ring there).
static func return_zone_center(level: BoardLevel) -> Vector2:
	return _ring_point(level, level.ball_radius + GUIDE_WALL_RADIUS)


## Radius of the return zone (a little under a ball, so only a ball that came back counts).
static func return_zone_radius(level: BoardLevel) -> float:
	return level.ball_radius


## Where a new ball is placed: against the ring in the channel, clear of the return zone
## below it. Starting in contact, the ball slides up the ring instead of bouncing off it.
static func launch_position(level: BoardLevel) -> Vector2:
	return _ring_point(level, GUIDE_WALL_RADIUS + level.ball_radius * 4.0)


## Unit direction to fire a ball in: along the channel, up the rail.
static func launch_direction(level: BoardLevel) -> Vector2:
	var angle := _lane_angle(level, GUIDE_WALL_RADIUS + level.ball_radius * 4.0)
	# d/dangle of (cos, sin) is (-sin, cos); the rail runs towards `_rail_sense()`.
	return Vector2(-sin(angle), cos(angle)) * _rail_sense(level)


## Where the ball leaves the channel into the field: riding the ring at `rail_end_deg`.
static func entry_point(level: BoardLevel) -> Vector2:
	return level.ring_center + _unit(level.rail_end_deg) * riding_radius(level)


## True when `point` lies in the flight lane under the top of the ring (see
## FLIGHT_LANE_DEPTH), where board builders leave no free pin.
static func in_flight_lane(level: BoardLevel, point: Vector2) -> bool:
	var rel := point - level.ring_center
	var degrees := rad_to_deg(rel.angle())
	return (
		level.ring_radius - rel.length() < FLIGHT_LANE_DEPTH
		and degrees > FLIGHT_LANE_FROM_DEG
		and degrees < FLIGHT_LANE_TO_DEG
	)


## The highest point (smallest y) a ball passes on its way from the launch position to the
## entry point.
static func highest_lane_y(level: BoardLevel) -> float:
	var top := minf(launch_position(level).y, entry_point(level).y)
	# Does the lane pass the top of the circle (-90° or 270°) between the end and the start?
	var low := minf(level.rail_start_deg, level.rail_end_deg)
	var high := maxf(level.rail_start_deg, level.rail_end_deg)
	for top_deg: float in [-450.0, -90.0, 270.0]:
		if top_deg >= low and top_deg <= high:
			top = minf(top, level.ring_center.y - riding_radius(level))
	return top


## The launch speed (px/s) a ball needs, ignoring friction, to climb to the top of the rail
## under `gravity_y` (px/s²). Launchers scale their power above this.
static func speed_to_clear(level: BoardLevel, gravity_y: float) -> float:
	var rise := launch_position(level).y - highest_lane_y(level)
	return sqrt(2.0 * maxf(gravity_y, 0.0) * maxf(rise, 0.0))


static func _unit(degrees: float) -> Vector2:
	var angle := deg_to_rad(degrees)
	return Vector2(cos(angle), sin(angle))


# Angle (radians) of the lane point `arc_length` pixels up the rail from its start.
static func _lane_angle(level: BoardLevel, arc_length: float) -> float:
	var radius := maxf(lane_radius(level), 1.0)
	return deg_to_rad(level.rail_start_deg) + _rail_sense(level) * arc_length / radius


# -1 when the rail runs through decreasing angles (the usual right-hand rail), else +1.
static func _rail_sense(level: BoardLevel) -> float:
	return -1.0 if level.rail_end_deg < level.rail_start_deg else 1.0


static func _ring_point(level: BoardLevel, arc_length: float) -> Vector2:
	var angle := _lane_angle(level, arc_length)
	return level.ring_center + Vector2(cos(angle), sin(angle)) * riding_radius(level)
