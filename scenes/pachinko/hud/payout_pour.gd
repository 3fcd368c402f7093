class_name PayoutPour
extends RefCounted
## The paid balls on their way into the cup: a payout is poured as drops that fall one after
## another from above the tray and land in it, each carrying its share of the balls, so the
## count in the cup rises as the balls land and a jackpot's hundred balls are seen to
## arrive. Time is the view's (real seconds): the rules have paid already.

## Most drops drawn for one payout (each carries its share of a bigger one).
const MAX_DROPS := 20
## Seconds between two drops of one payout.
const GAP := 0.06
## The drops' acceleration, px/s².
const GRAVITY := 1500.0
## The longest a payout waits behind the drops before it (a stream of payouts never leaves
## the count far behind the cup).
const MOST_WAIT := 1.0

## The drops in the air or waiting: x, height above the landing line, speed, seconds still
## to wait; and the balls each carries (same order).
var drops: Array[Vector4] = []
## Balls landed since the pour was made.
var landed := 0

var _balls := PackedInt32Array()


## Pours `balls` paid balls, in up to MAX_DROPS drops spread round `center_x` that fall
## from `height` px above the landing line, after the drops still waiting.
func pour(balls: int, center_x: float, height: float) -> void:
	if balls <= 0:
		return
	var count := mini(balls, MAX_DROPS)
	@warning_ignore("integer_division")
	var each := balls / count
	var extra := balls - each * count
	var wait := 0.0
	for drop in drops:
		wait = maxf(wait, drop.w)
	wait = minf(wait, MOST_WAIT)
	for i in count:
		var x := center_x + (float(i % 5) - 2.0) * 14.0
		drops.append(Vector4(x, maxf(height, 1.0), 0.0, wait + GAP * i))
		_balls.append(each + (1 if i < extra else 0))


## Lands every drop at once (the win card shows the tray's true count).
func land_all() -> void:
	landed += pending()
	drops.clear()
	_balls.clear()


## Balls still in the air or waiting to fall.
func pending() -> int:
	var total := 0
	for balls in _balls:
		total += balls
	return total


## Runs the pour for `delta` seconds; returns the balls that landed in it.
func advance(delta: float) -> int:
	var arrived := 0
	var i := 0
	while i < drops.size():
		var drop := drops[i]
		if drop.w > 0.0:
			drop.w -= delta
		else:
			drop.z += GRAVITY * delta
			drop.y -= drop.z * delta
		if drop.y <= 0.0:
			arrived += _balls[i]
			drops.remove_at(i)
			_balls.remove_at(i)
			continue
		drops[i] = drop
		i += 1
	landed += arrived
	return arrived
