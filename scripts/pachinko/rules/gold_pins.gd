class_name GoldPins
extends RefCounted
## Gold pins, without pictures: each game lights a set of pins (GoldPinPicker: spread so no
## one held strength reaches them all); a ball touching a lit one puts it out (the rules add
## a ball to the cup), and putting out the last gives the set's prize and lights a new set.
## The prize: a Gold spin on a board with reels (BonusMachine.grant_gold_spin), else a
## Gold rush (every catch pays double for RUSH_SECONDS of game time). The sets are drawn from a
## generator seeded from the game's seed, so a replay lights the same pins.

## Set `set_number` (1 for a game's first) lit `pins`.
signal set_lit(pins: PackedInt32Array, set_number: int)
## A ball put out gold pin `pin`; `left` are still lit in its set.
signal pin_out(pin: int, left: int)
## The last pin of set `set_number` went out; its prize (a Gold spin or a Gold rush) began.
signal set_cleared(set_number: int, gold_spin: bool)
## A Gold rush began or ended.
signal rush_changed(active: bool)

## Seconds of game time a Gold rush lasts.
const RUSH_SECONDS := 20.0
## What a catch pays during a Gold rush, as a multiple of its usual payout.
const RUSH_FACTOR := 2

## The pins of the set lit now (put out ones included), by world pin index.
var pins := PackedInt32Array()
## Pins put out, over every game.
var pins_out := 0
## Sets whose last pin went out, over every game.
var sets_cleared := 0
## The set lit now: 1 for a game's first.
var set_number := 0
## Seconds of Gold rush left (0: none on).
var rush_left := 0.0
## The pin reach the sets are drawn from (the chasing pilot reads it too).
var reach: PinReach

var _level: BoardLevel
var _bonus: BonusMachine
var _rng := RandomNumberGenerator.new()
var _size := 6
var _out: Dictionary[int, bool] = {}


## Gold pins for `level`; `rng_seed` fixes every set; `bonus` spins the Gold spins (none
## on a board without reels). The pins light with `light_first_set`.
func _init(level: BoardLevel, rng_seed: int, bonus: BonusMachine = null) -> void:
	_level = level
	_bonus = bonus
	_rng.seed = hash([rng_seed, "gold pins"])


## A game began: its first set lights and any Gold rush ends.
func light_first_set() -> void:
	if _level == null or _level.pins.is_empty():
		return
	if reach == null:
		reach = PinReach.of(_level)
		_size = GoldPinPicker.set_size(reach)
	set_number = 0
	_end_rush()
	_light_next()


## True while gold pin `pin` is lit (in the set and not yet put out).
func is_lit(pin: int) -> bool:
	return pins.has(pin) and not _out.has(pin)


## The set's pins still lit.
func lit_pins() -> PackedInt32Array:
	var out := PackedInt32Array()
	for pin in pins:
		if not _out.has(pin):
			out.append(pin)
	return out


## How many of the set's pins are still lit.
func left() -> int:
	return pins.size() - _out.size()


## A ball touched pin `pin`: returns true when that put out a lit gold pin (once per pin).
func touch(pin: int) -> bool:
	if not is_lit(pin):
		return false
	_out[pin] = true
	pins_out += 1
	pin_out.emit(pin, left())
	if left() == 0:
		sets_cleared += 1
		var spin := _bonus != null and _bonus.grant_gold_spin()
		if not spin:
			start_rush()
		set_cleared.emit(set_number, spin)
		_light_next()
	return true


## Starts a Gold rush (the prize on a board without reels), or lengthens one under way.
func start_rush() -> void:
	var was_on := rush_left > 0.0
	rush_left = RUSH_SECONDS
	if not was_on:
		rush_changed.emit(true)


## True when the prize is a Gold spin (the board has reels), false for a Gold rush.
func prize_is_spin() -> bool:
	return _bonus != null and _bonus.has_reels()


## True while a Gold rush is on.
func rush_on() -> bool:
	return rush_left > 0.0


## What a catch paying `payout` pays now (double during a Gold rush).
func boosted(payout: int) -> int:
	return payout * RUSH_FACTOR if rush_on() else payout


## Runs the Gold rush's clock for `seconds` of game time.
func advance(seconds: float) -> void:
	if rush_left <= 0.0:
		return
	rush_left -= seconds
	if rush_left <= 0.0:
		# said here: _end_rush says only a rush cut short (its time was left), so a rush that
		# ran out never told rush_changed(false) and the clear card waited on for it
		rush_left = 0.0
		rush_changed.emit(false)


## The counters the stats and the autoplay report.
func counters() -> Dictionary:
	return {"gold_pins_out": pins_out, "gold_sets": sets_cleared}


func _light_next() -> void:
	_out.clear()
	set_number += 1
	pins = GoldPinPicker.pick(_level, reach, _size, _rng)
	set_lit.emit(pins, set_number)


func _end_rush() -> void:
	if rush_left > 0.0:
		rush_left = 0.0
		rush_changed.emit(false)
