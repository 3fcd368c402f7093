class_name FlipperDrawback
extends RefCounted
## The flipper's drawback: how far the player has pulled it, 0..100, from a drag up the
## screen (press, drag_to), a held charge key (press, charge) or an analog trigger
## (set_power). It knows nothing of balls: PachinkoRules owns one, decides when a press may
## begin, and fires the loaded ball with the power `release` hands back.

## The drawback changed: power 0..100.
signal changed(power: float)

## Power added per second while a key or button is held: full power in 1.6 s, slow enough
## to stop at a power by feel (1.25 s was too quick in trial 5). Scaled by delta, so the
## same on any frame rate.
const CHARGE_PER_SECOND := 62.5

## Current drawback, 0..100.
var power := 0.0
## True between a press and its release (or cancel).
var drawing := false

var _origin := Vector2.ZERO


## The pointer went down at `at` (any coordinates, y down): drawback begins from zero.
func press(at: Vector2) -> void:
	drawing = true
	_origin = at
	_set_power(0.0)


## The pointer moved while drawing back: power is how far it went up from the press.
func drag_to(at: Vector2) -> void:
	if drawing:
		_set_power(LaunchPower.power_from_drag(_origin, at))


## Adds charge for a held key over `delta` seconds.
func charge(delta: float) -> void:
	if drawing:
		_set_power(minf(power + CHARGE_PER_SECOND * delta, LaunchPower.MAX_POWER))


## Sets the drawback directly (an analog trigger), 0..100.
func set_power(value: float) -> void:
	if drawing:
		_set_power(clampf(value, 0.0, LaunchPower.MAX_POWER))


## Lets go: returns the power the flipper was drawn to (0 when it was not drawing) and
## drops back to zero.
func release() -> float:
	if not drawing:
		return 0.0
	var drawn := power
	cancel()
	return drawn


## Lets go without firing (a pause mid-drawback, the end of a game): back to zero, and the
## next press starts afresh.
func cancel() -> void:
	drawing = false
	_set_power(0.0)


func _set_power(value: float) -> void:
	if value != power:
		power = value
		changed.emit(power)
