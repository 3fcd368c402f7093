class_name KeyNudge
extends RefCounted
## One axis of the keys' tilt (KeyTilt has two): a key press gives a nudge of fixed shape and
## length, however long the key stays down up to HOLD_SECONDS; a key held past that rolls the
## board on, smoothly, to full tilt; let go and it levels fast.
## Trial 9: "a 0.3 s tap moved a ball 60-120 px, Shift held 0.4 s moved 7 px: nothing in
## between", because a tap's tilt grew with the press's length, which a slow frame stretches.
## Works in whole ticks of KeyTilt.TICK (the caller's), so a press gives the same tilts at
## any frame rate. Values are parts of full tilt, signed (the sign is the direction).

## The nudge lasts this long (seconds), whatever the press's length (0.12 before the felt).
const NUDGE_SECONDS := 0.1
## A key held this long (seconds from its press) starts to roll the board on.
const HOLD_SECONDS := 0.22
## From HOLD_SECONDS, the hold reaches full tilt this much later, eased in and out.
const HOLD_RAMP_SECONDS := 0.45
## The tilt rises at most this much (part of full) per second: the nudge leans in a tick or
## two and never jolts.
const OUT_RATE := 12.0
## Full tilt back to level in this long (seconds): a key let go, or turned the other way.
const LEVEL_SECONDS := 0.08
## A key or stick axis under this is not held.
const HELD_AT := 0.2

## The tilt now (part of full, signed).
var value := 0.0

## The direction of the last press (-1, 0 or 1).
var _sign := 0.0
## Time since the last press (seconds); the nudge runs while it is under NUDGE_SECONDS.
var _since_press := INF
## How long the key has been held since its press (seconds).
var _held := 0.0
## The direction the key was held in at the last tick (to see a press no event announced).
var _was_held := 0.0
## A press the input events announced, waiting for the next tick (0: none).
var _pending := 0.0


## The hold's part of full tilt `held` seconds after the press: nothing before HOLD_SECONDS,
## then a smooth rise to 1 over HOLD_RAMP_SECONDS.
static func hold_part(held: float) -> float:
	return smoothstep(0.0, 1.0, (held - HOLD_SECONDS) / HOLD_RAMP_SECONDS)


## A key went down toward `direction` (its sign): the next tick starts a nudge, even if the
## key is up again by then (a press and release inside one frame still nudges).
func press(direction: float) -> void:
	if direction != 0.0:
		_pending = signf(direction)


## One tick of `seconds`: the key or stick at `held` (-1..1), a nudge of `nudge` (part of
## full) and a hold up to `hold_most` (part of full; less for the fine key).
func tick(seconds: float, held: float, nudge: float, hold_most: float) -> void:
	var held_sign := signf(held) if absf(held) >= HELD_AT else 0.0
	if _pending != 0.0:
		_start(_pending)
	elif held_sign != 0.0 and held_sign != _was_held:
		_start(held_sign)  # held with no press seen (a stick, or a test): a press all the same
	_pending = 0.0
	_was_held = held_sign
	var target := 0.0
	if _since_press < NUDGE_SECONDS - 0.0001:
		target = nudge
	if held_sign != 0.0 and held_sign == _sign:
		target = maxf(target, hold_part(_held) * hold_most * absf(held))
		_held += seconds
	else:
		_held = 0.0
	_since_press += seconds
	target *= _sign
	var levelling := absf(target) < absf(value) or target * value < 0.0
	var rate := 1.0 / LEVEL_SECONDS if levelling else OUT_RATE
	value = move_toward(value, target, rate * seconds)


## Takes over at `part` of full tilt (another control had the board): no press, no hold.
func take_over(part: float) -> void:
	value = part
	_sign = signf(part)
	_since_press = INF
	_held = 0.0


## Level, with no press waiting (a reset).
func reset() -> void:
	value = 0.0
	_sign = 0.0
	_since_press = INF
	_held = 0.0
	_was_held = 0.0
	_pending = 0.0


## True while a press waits for its tick.
func has_pending() -> bool:
	return _pending != 0.0


func _start(direction: float) -> void:
	_sign = direction
	_since_press = 0.0
	_held = 0.0
