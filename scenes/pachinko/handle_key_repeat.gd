class_name HandleKeyRepeat
extends RefCounted
## The handle's turn keys held down: one step at the press, then after FIRST_DELAY steady
## steps, faster the longer the key is held (from SLOW_INTERVAL to FAST_INTERVAL over
## SPEED_UP_SECONDS). The game's own repeat, not the system's: trial 8 held Left for half a
## second (xdotool, no key repeat from the display) and the handle moved one step.

## Seconds a key is held before it repeats.
const FIRST_DELAY := 0.3
## Seconds between repeated steps when the repeat begins, and once it is at full speed.
const SLOW_INTERVAL := 0.12
const FAST_INTERVAL := 0.03
## Seconds of repeating over which the steps speed up from slow to fast.
const SPEED_UP_SECONDS := 1.5

## The direction held: +1 stronger, -1 weaker, 0 none.
var direction := 0

var _held := 0.0
var _next_step := 0.0


## A turn key went down towards `toward` (+1 or -1): returns the step to take now (the
## press's own). A second key replaces the first.
func press(toward: int) -> int:
	direction = signi(toward)
	_held = 0.0
	_next_step = FIRST_DELAY
	return direction


## The key towards `toward` came up (another key's release leaves the held one going).
func release(toward: int) -> void:
	if signi(toward) == direction:
		stop()


## Stops repeating (the game paused, the handle was let go with everything else).
func stop() -> void:
	direction = 0
	_held = 0.0


## Counts `delta` seconds of holding: returns the steps due (signed: the direction times
## their number; 0 when nothing is held or none is due).
func advance(delta: float) -> int:
	if direction == 0 or delta <= 0.0:
		return 0
	_held += delta
	var steps := 0
	while _held >= _next_step:
		steps += 1
		_next_step += interval_at(_next_step)
	return steps * direction


## Seconds between repeated steps once a key has been held `held` seconds.
static func interval_at(held: float) -> float:
	var speed_up := clampf((held - FIRST_DELAY) / SPEED_UP_SECONDS, 0.0, 1.0)
	return lerpf(SLOW_INTERVAL, FAST_INTERVAL, speed_up)
