class_name RailTraffic
extends RefCounted
## Who is on the launch rail: the channel between the ring and the guide arc, from the
## launcher (`rail_start_deg`) to where it opens into the field (`rail_end_deg`).


## True when any ball in the channel is moving back down it (a weak shot rolling back).
## `positions` and `velocities` are the world's dense ball arrays.
static func ball_coming_down(
	level: BoardLevel, positions: PackedVector2Array, velocities: PackedVector2Array
) -> bool:
	var rail_outer := level.ring_radius
	var rail_inner := LaunchRail.guide_radius(level) + LaunchRail.GUIDE_WALL_RADIUS
	var low := deg_to_rad(minf(level.rail_start_deg, level.rail_end_deg))
	var high := deg_to_rad(maxf(level.rail_start_deg, level.rail_end_deg))
	var up_sign := -1.0 if level.rail_end_deg < level.rail_start_deg else 1.0
	for i in positions.size():
		var rel := positions[i] - level.ring_center
		var dist := rel.length()
		if dist < rail_inner or dist > rail_outer:
			continue
		var angle := rel.angle()
		# Bring the angle into the rail's range (the rail may cross ±180°).
		while angle > high:
			angle -= TAU
		while angle < low:
			angle += TAU
		if angle > high:
			continue
		# Up the rail is the direction of travel from start to end along the circle.
		var up := Vector2(-sin(angle), cos(angle)) * up_sign
		if velocities[i].dot(up) < 0.0:
			return true
	return false
