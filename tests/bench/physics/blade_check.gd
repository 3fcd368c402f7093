extends RefCounted
## The benchmark's tunnel counter for windmills, independent of the engine's own narrow
## phase: a ball tunnelled when its centre crossed a blade's core segment (pin to tip) in
## the blade's turning frame. Each move between two path points (the engine's substep ends,
## at evenly spaced times within the step) is taken into the frame of every wheel it comes
## near, with the wheel's angle at each end's time; a straight move there that crosses a
## blade's core is a tunnel, as a move through a pin's own radius is for SweptCheck.

## Counted tunnels: balls that crossed a blade in a step (once per ball and step).
var tunnels := 0

var _wheels: Array = []


## `scene["windmills"]`: [centre, blades, length, blade radius, ...] per wheel.
func _init(scene: Dictionary) -> void:
	_wheels = scene.get("windmills", [])


## Checks one step of `dt`: `before` and `after` positions by slot, the step's path points
## (see BallWorld.take_step_paths), and each wheel's angle and speed at the step's start.
func check_step(
	before: PackedVector2Array,
	after: PackedVector2Array,
	path_slots: PackedInt32Array,
	path_points: PackedVector2Array,
	angles: PackedFloat64Array,
	speeds: PackedFloat64Array,
	dt: float
) -> void:
	var k := 0
	for i: int in after.size():
		var points := PackedVector2Array([before[i]])
		while k < path_slots.size() and path_slots[k] < i:
			k += 1
		while k < path_slots.size() and path_slots[k] == i:
			points.append(path_points[k])
			k += 1
		points.append(after[i])
		if _crosses(points, angles, speeds, dt):
			tunnels += 1


# True when the ball's path `points` (evenly spaced in time over `dt`) crosses a blade.
func _crosses(
	points: PackedVector2Array, angles: PackedFloat64Array, speeds: PackedFloat64Array, dt: float
) -> bool:
	var n: int = points.size() - 1
	for m: int in _wheels.size():
		var wheel: Array = _wheels[m]
		var c: Vector2 = wheel[0]
		var reach: float = wheel[2] + wheel[3] + 40.0
		if (
			points[0].distance_squared_to(c) > reach * reach
			and points[n].distance_squared_to(c) > reach * reach
		):
			continue
		var blades: int = wheel[1]
		var length: float = wheel[2]
		for j: int in n:
			var t0: float = dt * float(j) / float(n)
			var t1: float = dt * float(j + 1) / float(n)
			# Into the wheel's frame at each end's time: the blades then stand still.
			var a: Vector2 = (points[j] - c).rotated(-(angles[m] + speeds[m] * t0))
			var b: Vector2 = (points[j + 1] - c).rotated(-(angles[m] + speeds[m] * t1))
			if a == b:
				continue
			for blade: int in blades:
				var tip := Vector2.from_angle(TAU * blade / blades) * length
				if Geometry2D.segment_intersects_segment(a, b, Vector2.ZERO, tip) != null:
					return true
	return false
