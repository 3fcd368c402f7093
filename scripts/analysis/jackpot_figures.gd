class_name JackpotFigures
extends RefCounted
## What a jackpot is worth and how often it comes, for the analysis report: a jackpot is
## JackpotRounds.ROUNDS rounds of the attackers open, with a break between two rounds, so it
## pays ROUNDS times a round's value and holds the reels (no spin starts) for all its
## rounds and breaks. BonusEstimate measures a round; these turn it into a jackpot.


## Balls one jackpot pays when each round pays `round_value`.
static func payout(round_value: float) -> float:
	return JackpotRounds.ROUNDS * round_value


## Seconds one jackpot lasts when each round lasts `round_seconds`: its rounds and the
## breaks between them.
static func seconds(round_seconds: float) -> float:
	return (
		JackpotRounds.ROUNDS * round_seconds
		+ (JackpotRounds.ROUNDS - 1) * JackpotRounds.BREAK_SECONDS
	)


## Jackpots an hour for a player firing a shot every `shot_interval` seconds who gets
## `per_shot` jackpots a shot.
static func per_hour(per_shot: float, shot_interval: float) -> float:
	return per_shot * 3600.0 / maxf(shot_interval, 0.01)
