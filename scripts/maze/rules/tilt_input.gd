class_name TiltInput
extends RefCounted
## How the player's input becomes a tilt, as in the seed: the joystick head travels ±15 px
## per axis and the largest tilt is 12° per axis; near the centre a dead zone and a gentle
## curve (trial 8: "a 14 px drag rolled the balls all the way across").
## Tilt is a Vector2 in degrees: +x rolls balls right, +y rolls them down the screen.
## (The forces a tilt makes are the physics layer's `MazeTilt`.)

## Largest tilt per axis, in degrees.
const MAX_TILT_DEG := 12.0
## The joystick head moves at most this far from its centre per axis, in seed pixels.
const JOYSTICK_RANGE := 15.0
## The joystick's dead zone, a part of its travel per axis: a head this near the centre
## leaves the board level (a hand resting on the mouse).
const JOYSTICK_DEAD_ZONE := 0.1
## Past the dead zone, the part u (0..1) of the rest of the travel tilts the board
## (1 - JOYSTICK_SQUARE) u + JOYSTICK_SQUARE u² of full tilt: a quarter of the way out gives
## 0.8°, half 3.3°, the whole 12°, where the seed's straight line gave 3°, 6° and 12°.
const JOYSTICK_SQUARE := 0.7
## Accelerometer tilt eases toward its target at this rate (1/s): smooth, not instant.
const EASE_RATE := 7.0
## ...and back toward level at this faster rate.
const RELEASE_RATE := 20.0


## Clamps a tilt to ±MAX_TILT_DEG per axis; non-finite components become 0.
static func clamp_tilt(tilt_deg: Vector2) -> Vector2:
	var x := tilt_deg.x if is_finite(tilt_deg.x) else 0.0
	var y := tilt_deg.y if is_finite(tilt_deg.y) else 0.0
	return Vector2(clampf(x, -MAX_TILT_DEG, MAX_TILT_DEG), clampf(y, -MAX_TILT_DEG, MAX_TILT_DEG))


## Clamps a joystick head offset (seed pixels) to ±JOYSTICK_RANGE per axis.
static func clamp_joystick(offset: Vector2) -> Vector2:
	return Vector2(
		clampf(offset.x, -JOYSTICK_RANGE, JOYSTICK_RANGE),
		clampf(offset.y, -JOYSTICK_RANGE, JOYSTICK_RANGE)
	)


## The tilt a joystick head offset asks for: level in the dead zone, then the gentle curve
## (JOYSTICK_SQUARE) to 12° at 15 px.
static func tilt_from_joystick(offset: Vector2) -> Vector2:
	var head := clamp_joystick(offset) / JOYSTICK_RANGE
	return Vector2(_stick_curve(head.x), _stick_curve(head.y)) * MAX_TILT_DEG


## The joystick head offset that shows a tilt (the inverse of `tilt_from_joystick`; level
## shows the head at the centre).
static func joystick_from_tilt(tilt_deg: Vector2) -> Vector2:
	var part := clamp_tilt(tilt_deg) / MAX_TILT_DEG
	return Vector2(_stick_travel(part.x), _stick_travel(part.y)) * JOYSTICK_RANGE


# Tilt (part of full, signed) for a head at `d` (part of its travel, signed).
static func _stick_curve(d: float) -> float:
	var u := maxf(absf(d) - JOYSTICK_DEAD_ZONE, 0.0) / (1.0 - JOYSTICK_DEAD_ZONE)
	return signf(d) * ((1.0 - JOYSTICK_SQUARE) * u + JOYSTICK_SQUARE * u * u)


# The head's travel (part, signed) for a tilt of `f` (part of full, signed): `_stick_curve`
# undone, the root of JOYSTICK_SQUARE u² + (1 - JOYSTICK_SQUARE) u = |f|.
static func _stick_travel(f: float) -> float:
	if f == 0.0:
		return 0.0
	var a := JOYSTICK_SQUARE
	var b := 1.0 - JOYSTICK_SQUARE
	var u := (-b + sqrt(b * b + 4.0 * a * absf(f))) / (2.0 * a)
	return signf(f) * (JOYSTICK_DEAD_ZONE + u * (1.0 - JOYSTICK_DEAD_ZONE))


## A stick or key vector (each axis -1..1) as a target tilt.
static func tilt_from_vector(v: Vector2) -> Vector2:
	return clamp_tilt(v * MAX_TILT_DEG)


## Moves `current` toward `target` for `delta` seconds, exponentially (frame-rate free): each
## axis at EASE_RATE while it tilts further the same way, at RELEASE_RATE back toward level.
static func ease_toward(current: Vector2, target: Vector2, delta: float) -> Vector2:
	var dt := maxf(delta, 0.0)
	return Vector2(_ease_axis(current.x, target.x, dt), _ease_axis(current.y, target.y, dt))


static func _ease_axis(current: float, target: float, delta: float) -> float:
	var levelling := absf(target) < absf(current) or signf(target) * signf(current) < 0.0
	var rate := RELEASE_RATE if levelling else EASE_RATE
	return lerpf(current, target, 1.0 - exp(-rate * delta))


## Tilt from an accelerometer reading (m/s², device axes) relative to a calibrated neutral
## reading, scaled by `sensitivity`. Phones report +x to the right and +y toward the top
## edge, so tipping the top edge down (y falls) rolls balls up the screen.
static func tilt_from_accelerometer(
	reading: Vector3, neutral: Vector3, sensitivity: float
) -> Vector2:
	var g := maxf(neutral.length(), 1.0)
	var dx := clampf((reading.x - neutral.x) / g, -1.0, 1.0)
	var dy := clampf((reading.y - neutral.y) / g, -1.0, 1.0)
	var deg := Vector2(rad_to_deg(asin(dx)), -rad_to_deg(asin(dy)))
	return clamp_tilt(deg * sensitivity)
