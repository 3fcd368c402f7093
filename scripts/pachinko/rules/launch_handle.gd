class_name LaunchHandle
extends RefCounted
## The handle of a real pachinko machine: while the player holds it, the launcher fires the
## loaded ball at the handle's strength every INTERVAL seconds (100 balls a minute); turning
## it changes the strength, and letting go stops the stream. The strength stays where it was
## set, so the next hold fires as the last one did. PachinkoRules owns one (`rules.handle`)
## and fires the balls it asks for; input calls grip / let_go / set_power on it directly.

## Gripped or let go, or the strength changed (0..100).
signal changed(held: bool, power: float)

## Seconds between two balls of the stream: 100 a minute, a real machine's legal pace.
const INTERVAL := 0.6
## The strength a new game's handle starts at.
const DEFAULT_POWER := 60.0
## A handle's spring never strikes two balls quite alike: each ball of the stream goes at
## the set strength plus or minus up to this. Without it every ball would take the same
## path (the simulation is exact), and one lucky strength would pay forever. At 2 it still
## did: a play trial held the best strength and its game never ended (1.77 balls back a
## ball over ten minutes on Classic); at 6 the stream spreads over a few pins' width, so
## a strength pays what its part of the field pays (tools/power_returns.gd measures it).
const JITTER := 6.0
const MAX_POWER := 100.0

## True while the handle is held.
var held := false
## The strength the stream fires at, 0..100.
var power := DEFAULT_POWER

var _wait := 0.0


## Takes hold of the handle: the first ball goes as soon as one is loaded.
func grip() -> void:
	if not held:
		held = true
		_wait = 0.0
		changed.emit(held, power)


## Lets go: the stream stops (the strength stays set).
func let_go() -> void:
	if held:
		held = false
		changed.emit(held, power)


## Sets the strength, clamped to 0..100.
func set_power(value: float) -> void:
	var before := power
	power = clampf(value, 0.0, MAX_POWER)
	if power != before:
		changed.emit(held, power)


## Advances `delta` seconds; true when the next ball of the stream is due. The caller fires
## and calls `fired()`; a ball it could not fire (none loaded, rail busy) stays due.
func update(delta: float) -> bool:
	if not held:
		return false
	_wait -= delta
	return _wait <= 0.0


## The strength for the next ball of the stream: the set one, jittered by `rng`.
func shot_power(rng: RandomNumberGenerator) -> float:
	return clampf(power + rng.randf_range(-JITTER, JITTER), 0.0, MAX_POWER)


## A ball of the stream went: the next one is due INTERVAL seconds later.
func fired() -> void:
	_wait += INTERVAL
	if _wait <= 0.0:
		_wait = INTERVAL
