class_name ReelSet
extends RefCounted
## The three digital reels a start pocket spins. A spin's result is fixed when it starts
## (drawn by BonusMachine from the game's seeded generator); the reels then stop one by one,
## left to right. When the first two already match (a "reach"), the last reel keeps the
## player waiting REACH_EXTRA seconds longer, turning slower and slower. Time is game time,
## so a replay stops them identically.

## A reel stopped showing `symbol`.
signal reel_stopped(reel: int, symbol: int)
## Every reel stopped; `jackpot` when all three show the same symbol.
signal spin_finished(result: PackedInt32Array, jackpot: bool)

const REELS := 3
## Seconds after the start at which each reel stops.
const STOP_SECONDS: Array[float] = [0.9, 1.4, 1.9]
## Extra seconds the last reel spins during a reach (the game view also slows its clock
## then, so on screen it lasts longer still).
const REACH_EXTRA := 2.0
## Symbols a rolling reel passes per second.
const ROLL_RATE := 14.0
## The last reel of a reach slows to this share of ROLL_RATE by the time it stops.
const REACH_END_RATE := 0.15
## Pause after the last reel stops before the next spin may start, seconds.
const SETTLE_SECONDS := 0.5

## Symbols per reel of the spin under way (or the last one).
var symbols := BonusPocketSpec.DEFAULT_SYMBOLS
## The spin's result: one symbol per reel.
var result := PackedInt32Array([0, 0, 0])
## Reels stopped so far in this spin (REELS when idle).
var stopped := REELS
## Seconds since the spin started.
var elapsed := 0.0
## False until the first spin: the reels then show no number (a face of three equal
## numbers before any spin would read as a jackpot).
var spun := false


## True from a spin's start until its result has settled (never before the first spin).
func busy() -> bool:
	if not spun:
		return false
	return stopped < REELS or elapsed < _last_stop() + SETTLE_SECONDS


## Starts a spin that will land on `landing` (REELS symbols below `symbol_count`).
func start(landing: PackedInt32Array, symbol_count: int) -> void:
	symbols = maxi(symbol_count, 1)
	spun = true
	result = landing.duplicate()
	stopped = 0
	elapsed = 0.0


## True when the first two reels match, so the last one is the decider.
func is_reach() -> bool:
	return result.size() == REELS and result[0] == result[1]


## True when every reel shows the same symbol.
func is_jackpot() -> bool:
	return is_reach() and result[1] == result[2]


## True while the last reel of a reach is still turning (the moment the view stages).
func in_reach() -> bool:
	return stopped == REELS - 1 and is_reach()


## How far a reach has gone, 0 when the second reel stopped .. 1 as the last one stops
## (0 when there is no reach under way).
func reach_progress() -> float:
	if not in_reach():
		return 0.0
	var from := stop_time(REELS - 2)
	return clampf((elapsed - from) / maxf(stop_time(REELS - 1) - from, 0.001), 0.0, 1.0)


## The seconds at which reel `reel` stops in this spin.
func stop_time(reel: int) -> float:
	var at: float = STOP_SECONDS[clampi(reel, 0, REELS - 1)]
	if reel == REELS - 1 and is_reach():
		at += REACH_EXTRA
	return at


## Runs the reels for `delta` seconds; stops each reel whose time has come.
func advance(delta: float) -> void:
	if not busy():
		return
	elapsed += delta
	while stopped < REELS and elapsed >= stop_time(stopped):
		stopped += 1
		reel_stopped.emit(stopped - 1, result[stopped - 1])
		if stopped == REELS:
			spin_finished.emit(result, is_jackpot())


## The symbol reel `reel` shows now: its result once stopped, else a rolling symbol (for
## drawing; the rolling one depends on time only); -1 before the first spin.
func shown_symbol(reel: int) -> int:
	if not spun:
		return -1
	if reel < stopped:
		return result[reel]
	return (int(roll_position(reel)) + reel * 2 + result[reel]) % symbols


## How many symbols reel `reel` has rolled past since the spin began (for drawing): the
## last reel of a reach slows down evenly to REACH_END_RATE.
func roll_position(reel: int) -> float:
	if reel != REELS - 1 or not is_reach():
		return elapsed * ROLL_RATE
	var from := stop_time(REELS - 2)
	if elapsed <= from:
		return elapsed * ROLL_RATE
	var span := maxf(stop_time(REELS - 1) - from, 0.001)
	var t := minf(elapsed - from, span)
	var slowing := (1.0 - REACH_END_RATE) * 0.5 * t * t / span
	return from * ROLL_RATE + (t - slowing) * ROLL_RATE


## True while reel `reel` is still turning.
func is_spinning(reel: int) -> bool:
	return reel >= stopped


func _last_stop() -> float:
	return stop_time(REELS - 1)
