class_name JackpotRounds
extends RefCounted
## A jackpot's rounds, counted as a real machine counts them (大当たり ラウンド): the
## jackpot opens the attackers for round 1 of ROUNDS; a round ends when every attacker has
## shut (its catches or its seconds used up, BonusMachine decides); after a short break the
## next round opens, and after the last one the jackpot is over. It keeps the balls the
## jackpot paid. Time is game time, so a replay counts the same rounds.

## Round `round` of `rounds` began: the attackers open.
signal round_started(round: int, rounds: int)
## Round `round` of `rounds` ended: the attackers are shut.
signal round_ended(round: int, rounds: int)
## The last round ended; the jackpot paid `paid` balls in all.
signal finished(paid: int)

## Rounds in a jackpot.
const ROUNDS := 10
## Seconds between two rounds with the attackers shut (the lid's flutter on a machine).
const BREAK_SECONDS := 1.5

## The round under way or in its break (1..ROUNDS), 0 when no jackpot is on.
var current_round := 0
## Balls paid since the jackpot began.
var paid := 0

var _break_left := 0.0


## True from a jackpot's first round to the end of its last.
func active() -> bool:
	return current_round > 0


## True between two rounds.
func in_break() -> bool:
	return active() and _break_left > 0.0


## A jackpot came: round 1 begins. A jackpot under way is not restarted.
func begin() -> void:
	if active():
		return
	current_round = 1
	paid = 0
	_break_left = 0.0
	round_started.emit(current_round, ROUNDS)


## The attackers of the round under way have all shut: the round is over, and after the
## last round so is the jackpot.
func end_round() -> void:
	if not active() or in_break():
		return
	round_ended.emit(current_round, ROUNDS)
	if current_round >= ROUNDS:
		var total := paid
		current_round = 0
		finished.emit(total)
	else:
		_break_left = BREAK_SECONDS


## Counts `balls` an attacker paid while the jackpot is on.
func add_paid(balls: int) -> void:
	if active():
		paid += maxi(balls, 0)


## Runs the break for `delta` seconds; the next round begins when it is over.
func advance(delta: float) -> void:
	if not in_break() or delta <= 0.0:
		return
	_break_left -= delta
	if _break_left <= 0.0:
		_break_left = 0.0
		current_round += 1
		round_started.emit(current_round, ROUNDS)
