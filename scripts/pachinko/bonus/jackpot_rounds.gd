class_name JackpotRounds
extends RefCounted
## A jackpot's rounds, counted as a real machine counts them (大当たり ラウンド): the
## jackpot opens the attackers for round 1 of ROUNDS; a round ends when every attacker has
## shut (its catches or its seconds used up, BonusMachine decides); after a short break the
## next round opens, and after the last one the jackpot is over. It keeps the balls the
## jackpot paid. Time is game time, so a replay counts the same rounds. A jackpot that comes
## within AGAIN_WINDOW seconds of the last one's end is announced first: its round 1 opens
## after AGAIN_SECONDS (trial 8: "JACKPOT OVER" covered a new jackpot whose round 1 clock was
## already running).

## A jackpot came back to back with the last: its round 1 opens in AGAIN_SECONDS.
signal again_announced
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
## A jackpot this many seconds (game time) after the last one's end is a jackpot again.
const AGAIN_WINDOW := 15.0
## Seconds a jackpot again is announced before its round 1 opens.
const AGAIN_SECONDS := 5.0

## The round under way or in its break (1..ROUNDS), 0 when no jackpot is on.
var current_round := 0
## Balls paid since the jackpot began.
var paid := 0

var _break_left := 0.0
# Seconds since the last jackpot ended (INF: none yet this game).
var _since_end := INF
# True while a jackpot again is announced, before its round 1 opens.
var _announcing := false


## True from a jackpot's first round to the end of its last.
func active() -> bool:
	return current_round > 0


## True between two rounds.
func in_break() -> bool:
	return active() and _break_left > 0.0


## True while a jackpot again is announced and its round 1 has not opened yet.
func announcing() -> bool:
	return _announcing


## A jackpot came: round 1 begins, or, back to back with the last one, is announced first.
## A jackpot under way is not restarted.
func begin() -> void:
	if active():
		return
	current_round = 1
	paid = 0
	_break_left = 0.0
	if _since_end < AGAIN_WINDOW:
		_announcing = true
		_break_left = AGAIN_SECONDS  # a break before round 1: nothing is open, no clock runs
		again_announced.emit()
		return
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
		_since_end = 0.0
		finished.emit(total)
	else:
		_break_left = BREAK_SECONDS


## Counts `balls` an attacker paid while the jackpot is on.
func add_paid(balls: int) -> void:
	if active():
		paid += maxi(balls, 0)


## Counts `delta` seconds with no break running (the time since the last jackpot ended).
func count_time(delta: float) -> void:
	_since_end += maxf(delta, 0.0)


## Runs the break for `delta` seconds; the next round begins when it is over (round 1 after
## a jackpot again's announcement).
func advance(delta: float) -> void:
	if not in_break() or delta <= 0.0:
		return
	_break_left -= delta
	if _break_left <= 0.0:
		_break_left = 0.0
		if _announcing:
			_announcing = false
		else:
			current_round += 1
		round_started.emit(current_round, ROUNDS)
