class_name KeyTilt
extends RefCounted
## The board's tilt from keys and a gamepad stick (trial 8: "a 0.2 s tap moved a ball 10 px,
## a 0.25 s one sent it across the board"; "still tilted 0.4 s after release").
##
## A held key pushes a "push" (0..1 per axis) up at a steady rate, and the tilt is a curve of
## the push (KEY_CURVE): a quick lean to about 1.4°, then a long gentle part (a tap of 0.1 to
## 0.4 s gives a nudge that grows steadily with the tap's length), then the rest of the way
## to full tilt for a key held KEY_FULL_SECONDS. Let go and the push falls back to level in
## KEY_LEVEL_SECONDS (under 0.1 s), so a counter-tap brakes the ball it pushed.
## The push is integrated in fixed ticks of TICK seconds, never per frame: the same press
## gives the same tilts at any frame rate. Holding the fine key halves the tilt (FINE_SCALE).
## Tilt in degrees per axis, as TiltInput's.

## The tilt is worked out in ticks this long (the maze world's step).
const TICK := 1.0 / 120.0
## A key held this long reaches full tilt.
const KEY_FULL_SECONDS := 0.7
## Let go: from full tilt back to level in this long.
const KEY_LEVEL_SECONDS := 0.08
## The tilt (fraction of full) at each push (0..1): a quick lean, a long gentle part, then
## the rest. Straight lines between the points; each pair rises.
const KEY_CURVE: Array[Vector2] = [
	Vector2(0.0, 0.0), Vector2(0.06, 0.12), Vector2(0.75, 0.16), Vector2(1.0, 1.0)
]
## With the fine key held the tilt is this part of the usual one.
const FINE_SCALE := 0.5
## The fine key's change eases in over this long (no jolt when it is pressed mid-hold).
const FINE_EASE_SECONDS := 0.1

## The push per axis (-1..1; the sign is the direction).
var push := Vector2.ZERO
## The tilt scale now (1, or FINE_SCALE while the fine key is held; eased between).
var scale := 1.0

var _time := 0.0


## The tilt (fraction of full, 0..1) for a push of `p` (0..1), by KEY_CURVE.
static func curve(p: float) -> float:
	var at := clampf(p, 0.0, 1.0)
	for i in range(1, KEY_CURVE.size()):
		var a := KEY_CURVE[i - 1]
		var b := KEY_CURVE[i]
		if at <= b.x:
			return lerpf(a.y, b.y, (at - a.x) / (b.x - a.x))
	return 1.0


## The push (0..1) whose tilt is `fraction` of full (the inverse of `curve`).
static func push_for(fraction: float) -> float:
	var at := clampf(fraction, 0.0, 1.0)
	for i in range(1, KEY_CURVE.size()):
		var a := KEY_CURVE[i - 1]
		var b := KEY_CURVE[i]
		if at <= b.y:
			return lerpf(a.x, b.x, (at - a.y) / (b.y - a.y))
	return 1.0


## Starts from `tilt_deg` (another control had the board): the push that shows it.
func take_over(tilt_deg: Vector2) -> void:
	var full := TiltInput.MAX_TILT_DEG * maxf(scale, 0.01)
	push = Vector2(
		signf(tilt_deg.x) * push_for(absf(tilt_deg.x) / full),
		signf(tilt_deg.y) * push_for(absf(tilt_deg.y) / full)
	)


## Runs `delta` seconds with the keys or stick at `keys` (each axis -1..1), the fine key
## held or not, and `sensitivity` (the settings' tilt sensitivity) scaling the tilt. Whole
## ticks only; the rest waits for the next call. Returns the tilt in degrees.
func update(delta: float, keys: Vector2, fine: bool, sensitivity := 1.0) -> Vector2:
	var v := keys.limit_length(1.0)
	var goal := Vector2(signf(v.x) * push_for(absf(v.x)), signf(v.y) * push_for(absf(v.y)))
	var goal_scale := FINE_SCALE if fine else 1.0
	_time += maxf(delta, 0.0) if is_finite(delta) else 0.0
	while _time >= TICK:
		_time -= TICK
		push = Vector2(_push_axis(push.x, goal.x), _push_axis(push.y, goal.y))
		scale = move_toward(scale, goal_scale, TICK / FINE_EASE_SECONDS * (1.0 - FINE_SCALE))
	return tilt(sensitivity)


## The tilt in degrees for the push and scale now.
func tilt(sensitivity := 1.0) -> Vector2:
	var full := TiltInput.MAX_TILT_DEG * scale * sensitivity
	return TiltInput.clamp_tilt(
		Vector2(signf(push.x) * curve(absf(push.x)), signf(push.y) * curve(absf(push.y))) * full
	)


## Back to level at once, the fine key let go (a reset).
func reset() -> void:
	push = Vector2.ZERO
	scale = 1.0
	_time = 0.0


## Moves `tilt_deg` toward level for `delta` seconds at the keys' levelling speed (full tilt
## to level in KEY_LEVEL_SECONDS): the board after a win, as a key let go.
static func level_toward(tilt_deg: Vector2, delta: float) -> Vector2:
	var step := TiltInput.MAX_TILT_DEG / KEY_LEVEL_SECONDS * maxf(delta, 0.0)
	return Vector2(move_toward(tilt_deg.x, 0.0, step), move_toward(tilt_deg.y, 0.0, step))


# One tick of one axis: toward level at the levelling rate (a key let go or turned the other
# way), further out at the tilting rate.
static func _push_axis(current: float, goal: float) -> float:
	var out_step := TICK / KEY_FULL_SECONDS
	var back_step := TICK / KEY_LEVEL_SECONDS
	if signf(goal) * signf(current) < 0.0 or absf(goal) < absf(current):
		var target := 0.0 if signf(goal) * signf(current) < 0.0 else goal
		return move_toward(current, target, back_step)
	return move_toward(current, goal, out_step)
