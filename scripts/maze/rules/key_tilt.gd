class_name KeyTilt
extends RefCounted
## The board's tilt from keys and a gamepad stick: a tap is a fixed nudge, a hold rolls on.
## Trial 9: "a 0.3 s tap moved a ball 60-120 px, once 130; Shift held 0.4 s moved 7 px:
## nothing in between", because a tap's tilt grew with the press's length (trial 8's ramp),
## and a slow frame or a busy machine stretches a press.
##
## Each axis is a KeyNudge: a key press starts a nudge of NUDGE of full tilt for
## KeyNudge.NUDGE_SECONDS, whatever the press's length up to KeyNudge.HOLD_SECONDS (the same
## nudge for a 0.05 s and a 0.2 s press, and for a press and release inside one frame, which
## `press` hears from the input event); held on past that, the board rolls smoothly on to full
## tilt; let go and it levels in KeyNudge.LEVEL_SECONDS, so a counter-tap brakes.
## The tilt is worked out in fixed ticks of TICK seconds, never per frame: the same press
## gives the same tilts at any frame rate. The fine key halves the hold's tilt and the nudge's
## travel (FINE_NUDGE), eased in over FINE_EASE_SECONDS. Tilt in degrees per axis, as
## TiltInput's.

## The tilt is worked out in ticks this long (the maze world's step).
const TICK := 1.0 / 120.0
## A tap's tilt, a part of full tilt (6.6°): a resting ball rolls about a third of a corridor
## cell (13 board px on Switchbacks' 35 px cells; see README's tap table). A short, firm push:
## the felt near level (MazeTilt.felt_drag) soon stops what it rolls, so a second tap finds
## the ball at rest and rolls it as far again (trial 10; 3° before the felt).
const NUDGE := 0.55
## The nudge with the fine key held: the ball rolls about half as far (friction takes a
## fixed part of a small tilt, so half the travel needs more than half the tilt).
const FINE_NUDGE := 0.36
## With the fine key held the hold's tilt is this part of the usual one.
const FINE_SCALE := 0.5
## The fine key's change eases in over this long (no jolt when it is pressed mid-hold).
const FINE_EASE_SECONDS := 0.1
## Let go: from full tilt back to level in this long.
const KEY_LEVEL_SECONDS := KeyNudge.LEVEL_SECONDS
## A key held this long is at full tilt.
const KEY_FULL_SECONDS := KeyNudge.HOLD_SECONDS + KeyNudge.HOLD_RAMP_SECONDS

## The tilt actions and the way each tilts.
const DIRECTIONS := {
	&"tilt_left": Vector2.LEFT,
	&"tilt_right": Vector2.RIGHT,
	&"tilt_up": Vector2.UP,
	&"tilt_down": Vector2.DOWN,
}

## The tilt scale now (1, or FINE_SCALE while the fine key is held; eased between).
var scale := 1.0

var _x := KeyNudge.new()
var _y := KeyNudge.new()
var _time := 0.0


## A key (or stick) went down toward `direction` (each axis's sign): its nudge starts at the
## next tick even if the key is up again by then.
func press(direction: Vector2) -> void:
	_x.press(direction.x)
	_y.press(direction.y)


## The direction of the tilt keys that `event` presses (zero for anything else: a key's
## repeat, a stick's move): the game hands it to `press`, so a press shorter than a frame
## still counts.
static func pressed_direction(event: InputEvent) -> Vector2:
	var direction := Vector2.ZERO
	if event is InputEventJoypadMotion:
		# every move of a pushed stick reads as a press, and each would start the nudge again
		# and never let a hold build up: the stick's nudge comes from its held value instead
		return direction
	for action: StringName in DIRECTIONS:
		if event.is_action_pressed(action):
			direction += DIRECTIONS[action]
	return direction


## True while a press waits for its tick.
func has_pending() -> bool:
	return _x.has_pending() or _y.has_pending()


## Starts from `tilt_deg` (another control had the board), showing it.
func take_over(tilt_deg: Vector2) -> void:
	var part := TiltInput.clamp_tilt(tilt_deg) / TiltInput.MAX_TILT_DEG
	_x.take_over(part.x)
	_y.take_over(part.y)


## Runs `delta` seconds with the keys or stick at `keys` (each axis -1..1), the fine key
## held or not, and `sensitivity` (the settings' tilt sensitivity) scaling the tilt. Whole
## ticks only; the rest waits for the next call. Returns the tilt in degrees.
func update(delta: float, keys: Vector2, fine: bool, sensitivity := 1.0) -> Vector2:
	var v := keys.limit_length(1.0)
	var goal_scale := FINE_SCALE if fine else 1.0
	_time += maxf(delta, 0.0) if is_finite(delta) else 0.0
	while _time >= TICK:
		_time -= TICK
		scale = move_toward(scale, goal_scale, TICK / FINE_EASE_SECONDS * (1.0 - FINE_SCALE))
		var nudge := remap(scale, FINE_SCALE, 1.0, FINE_NUDGE, NUDGE)
		_x.tick(TICK, v.x, nudge, scale)
		_y.tick(TICK, v.y, nudge, scale)
	return tilt(sensitivity)


## The tilt in degrees now.
func tilt(sensitivity := 1.0) -> Vector2:
	return TiltInput.clamp_tilt(Vector2(_x.value, _y.value) * TiltInput.MAX_TILT_DEG * sensitivity)


## Back to level at once, the fine key let go, no press waiting (a reset).
func reset() -> void:
	_x.reset()
	_y.reset()
	scale = 1.0
	_time = 0.0


## Moves `tilt_deg` toward level for `delta` seconds at the keys' levelling speed (full tilt
## to level in KEY_LEVEL_SECONDS): the board after a win or a loss, as a key let go.
static func level_toward(tilt_deg: Vector2, delta: float) -> Vector2:
	var step := TiltInput.MAX_TILT_DEG / KEY_LEVEL_SECONDS * maxf(delta, 0.0)
	return Vector2(move_toward(tilt_deg.x, 0.0, step), move_toward(tilt_deg.y, 0.0, step))
