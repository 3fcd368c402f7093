class_name ReachSlowMotion
extends RefCounted
## Slow motion for a reach: while the last reel of a reach turns, the game's clock eases
## down to SLOW_SCALE so the balls drift and the player watches the reel; after it stops the
## clock eases back. Only the clock slows: the rules run the same fixed steps, fewer a
## frame, so the physics, a replay and the state hash never know (the reel, on game time,
## slows on screen with them).

## How fast the clock runs at the slowest.
const SLOW_SCALE := 0.4
## Real seconds to ease from full speed to SLOW_SCALE, and back.
const EASE_SECONDS := 0.3

var _scale := 1.0


## The clock's factor for a frame of `real_delta` seconds with `machine`'s reels as they are.
func time_scale(machine: BonusMachine, real_delta: float) -> float:
	var wanted := SLOW_SCALE if machine != null and machine.reels.in_reach() else 1.0
	var rate := (1.0 - SLOW_SCALE) / EASE_SECONDS
	_scale = move_toward(_scale, wanted, maxf(real_delta, 0.0) * rate)
	return _scale


## Back to full speed at once (a new game).
func reset() -> void:
	_scale = 1.0
