class_name TiltInput
extends RefCounted
## How the player's input becomes a tilt, as in the seed: the joystick head travels ±15 px
## per axis and each pixel tilts the board 0.8°, so the largest tilt is 12° per axis.
## Tilt is a Vector2 in degrees: +x rolls balls right, +y rolls them down the screen.
## (The forces a tilt makes are the physics layer's `MazeTilt`.)

## Largest tilt per axis, in degrees.
const MAX_TILT_DEG := 12.0
## The joystick head moves at most this far from its centre per axis, in seed pixels.
const JOYSTICK_RANGE := 15.0
## Degrees of tilt per pixel of joystick travel (the seed's 0.8: 15 px → 12°).
const DEG_PER_JOYSTICK_PX := 0.8
## Accelerometer tilt eases toward its target at this rate (1/s): smooth, not instant.
const EASE_RATE := 7.0
## ...and back toward level at this faster rate.
const RELEASE_RATE := 20.0
## Keys and stick: a held key tilts the board further at a steady rate, reaching full tilt
## after this many seconds held, so a 0.15 s tap leans it a quarter of the way (3 degrees)
## and nudges a resting ball; only a hold sends it down a corridor (a play trial found the
## old ease, 65% of full tilt within 0.15 s, "all-or-nothing").
const KEY_FULL_SECONDS := 0.6
## ...and a key let go (or turned the other way) brings the board back to level at a steady
## rate too, from full tilt in this many seconds: it settles like the joystick let go, not
## with a jolt, and stops short of carrying a tapped ball on.
const KEY_LEVEL_SECONDS := 0.15


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


## The tilt a joystick head offset asks for: 0.8° per pixel, so 15 px gives 12°.
static func tilt_from_joystick(offset: Vector2) -> Vector2:
	return clamp_joystick(offset) * DEG_PER_JOYSTICK_PX


## The joystick head offset that shows a tilt (the inverse of `tilt_from_joystick`).
static func joystick_from_tilt(tilt_deg: Vector2) -> Vector2:
	return clamp_tilt(tilt_deg) / DEG_PER_JOYSTICK_PX


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


## Moves `current` toward `target` for `delta` seconds at the keys' steady rates: further
## from level at MAX_TILT_DEG per KEY_FULL_SECONDS, back toward level at MAX_TILT_DEG per
## KEY_LEVEL_SECONDS. Piecewise straight lines, so any split of the same time into frames
## gives the same tilt (frame-rate free).
static func ramp_toward(current: Vector2, target: Vector2, delta: float) -> Vector2:
	var dt := maxf(delta, 0.0)
	return Vector2(_ramp_axis(current.x, target.x, dt), _ramp_axis(current.y, target.y, dt))


static func _ramp_axis(current: float, target: float, delta: float) -> float:
	var tilt_rate := MAX_TILT_DEG / KEY_FULL_SECONDS
	var level_rate := MAX_TILT_DEG / KEY_LEVEL_SECONDS
	if signf(target) * signf(current) < 0.0:
		# turned the other way: back to level first, then on at the tilting rate
		var to_level := absf(current) / level_rate
		if delta <= to_level:
			return move_toward(current, 0.0, level_rate * delta)
		return move_toward(0.0, target, tilt_rate * (delta - to_level))
	var rate := level_rate if absf(target) < absf(current) else tilt_rate
	return move_toward(current, target, rate * delta)


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
