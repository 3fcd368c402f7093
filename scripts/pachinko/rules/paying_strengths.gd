class_name PayingStrengths
extends RefCounted
## Which launch strengths have been paying this game: every ball is counted in the band of
## the power it was launched at (BANDS bands over 0..100), with what it paid back (pockets,
## start pockets, tulips, attackers). The launcher's power bar lights the bands that paid,
## so a player streaming at one strength sees when another has been doing better (a blind
## trial: "little to decide once streaming"). One game's figures: a new game starts afresh.

## Bands across the power range (each 100 / BANDS points wide).
const BANDS := 10
## Balls launched in a band before its return is shown (fewer say too little).
const MIN_SHOTS := 3

var _band_of_ball := {}
var _shots := PackedInt32Array()
var _paid := PackedInt32Array()


func _init() -> void:
	_shots.resize(BANDS)
	_paid.resize(BANDS)


## The band power `power` (0..100) falls in.
static func band_of(power: float) -> int:
	return clampi(floori(power / (100.0 / BANDS)), 0, BANDS - 1)


## A ball was launched at `power`.
func note_launch(ball_id: int, power: float) -> void:
	var band := band_of(power)
	_band_of_ball[ball_id] = band
	_shots[band] += 1


## The ball `ball_id` paid `balls` back (a ball unknown here, e.g. placed by a test, is
## ignored).
func note_paid(ball_id: int, balls: int) -> void:
	if _band_of_ball.has(ball_id) and balls > 0:
		_paid[_band_of_ball[ball_id]] += balls


## Balls launched in `band` this game.
func shots(band: int) -> int:
	return _shots[band]


## Balls paid back per ball launched in `band` (0 until it has MIN_SHOTS shots).
func return_of(band: int) -> float:
	if _shots[band] < MIN_SHOTS:
		return 0.0
	return float(_paid[band]) / float(_shots[band])


## The band with the best return this game, -1 while none has paid.
func best_band() -> int:
	var best := -1
	for band in BANDS:
		if return_of(band) > 0.0 and (best < 0 or return_of(band) > return_of(best)):
			best = band
	return best
