class_name BonusEstimate
extends RefCounted
## What a board's bonus layer adds to the balls a player gets back, estimated from two
## analysis runs of the same shots: one with every bonus pocket shut (the plain analysis)
## and one with them all held open. The rules open them only now and then, so the shut run
## alone misses the jackpots and the open tulips; this adds them back with a small model of
## the player the return is measured for: single shots at uniform random power, one every
## SHOT_INTERVAL seconds on average (the autoplay's pace; a held handle fires one every
## LaunchHandle.INTERVAL, at one strength). The pace matters to the jackpots only: an open
## attacker's round lasts seconds, so it sees as many balls as are fired in them.
##
## - Tulips open after a catch and close after the next, so catches alternate shut and open:
##   a tulip catching at rate s shut and o open catches at 2·s·o / (s + o) per shot.
## - Start pockets queue spins; a spin lasts the reels' stop times (longer on a reach), and
##   no spin starts while an attacker is open. Spins run at the rate balls reach the start
##   pockets, up to what the reels can turn (a fluid model: no queue overflow counted).
## - A jackpot opens every attacker for JackpotRounds.ROUNDS rounds: in each, an attacker
##   catches at its open rate for its open seconds, up to its open catches, and pays its
##   payout per catch (JackpotFigures turns a round into a jackpot).
##
## The figures are expectations from measured rates, not a simulation of the rules; the
## autoplay (`--autoplay=pachinko --handle=P`) plays the real rules to check them.

## Seconds between single shots, on average: the autoplay's pause is drawn evenly from
## MIN_GAP to MAX_GAP after each shot. (It once was the handle's 0.6 s, and Fever's
## autoplay then paid 0.1 to 0.15 less than the estimate: its rounds saw fewer balls.)
const SHOT_INTERVAL := (PachinkoAutoplay.MIN_GAP + PachinkoAutoplay.MAX_GAP) * 0.5


## The bonus figures for `band` (or every band with -1): balls per shot the tulips and the
## jackpots add, jackpots per 1000 shots, and the model's inputs, as report data, for a
## player firing a ball every `shot_interval` seconds.
static func estimate(
	level: BoardLevel,
	shut: AnalysisTally,
	open: AnalysisTally,
	band := -1,
	shot_interval := SHOT_INTERVAL
) -> Dictionary:
	var shots := _shots(shut, band)
	var open_shots := _shots(open, band)
	if shots == 0 or open_shots == 0:
		return {"tulip_return": 0.0, "jackpot_return": 0.0, "jackpots_per_1000": 0.0}
	var fire_rate := 1.0 / maxf(shot_interval, 0.01)
	var tulip_extra := 0.0
	var start_rate := 0.0
	var jackpot_weight := 0.0
	var reach_weight := 0.0
	var round_value := 0.0
	var round_seconds := 0.0
	for i in level.bonus_pockets.size():
		var spec := level.bonus_pockets[i]
		var id := BonusGeometry.pocket_id(level, i)
		var shut_rate := float(_hits(shut, band, id)) / shots
		var open_rate := float(_hits(open, band, id)) / open_shots
		match spec.role:
			BonusPocketSpec.Role.TULIP:
				if shut_rate > 0.0 and open_rate > 0.0:
					var alternating := 2.0 * shut_rate * open_rate / (shut_rate + open_rate)
					tulip_extra += (alternating - shut_rate) * maxi(spec.payout, 0)
			BonusPocketSpec.Role.START:
				var symbols := float(maxi(spec.symbols, 1))
				start_rate += shut_rate
				jackpot_weight += shut_rate / (symbols * symbols)
				reach_weight += shut_rate / symbols
			BonusPocketSpec.Role.ATTACKER:
				var balls := fire_rate * spec.open_seconds
				var catches := minf(float(spec.open_catches), open_rate * balls)
				round_value += catches * maxi(spec.payout, 0)
				var seconds := spec.open_seconds
				if open_rate > 0.0:
					seconds = minf(seconds, spec.open_catches / (open_rate * fire_rate))
				round_seconds = maxf(round_seconds, seconds)
	var jackpot_odds := jackpot_weight / start_rate if start_rate > 0.0 else 0.0
	var reach_odds := reach_weight / start_rate if start_rate > 0.0 else 0.0
	var spin_seconds := _spin_seconds(reach_odds)
	var jackpot_seconds := JackpotFigures.seconds(round_seconds) if round_value > 0.0 else 0.0
	var most_spins := 1.0 / (spin_seconds + jackpot_odds * jackpot_seconds)
	var spins_per_second := minf(start_rate * fire_rate, most_spins)
	var jackpots_per_shot := spins_per_second * jackpot_odds / fire_rate
	var payout := JackpotFigures.payout(round_value)
	return {
		"tulip_return": tulip_extra,
		"jackpot_return": jackpots_per_shot * payout,
		"jackpots_per_1000": jackpots_per_shot * 1000.0,
		"jackpots_per_hour": JackpotFigures.per_hour(jackpots_per_shot, shot_interval),
		"jackpot_payout": payout,
		"round_value": round_value,
		"jackpot_odds": jackpot_odds,
	}


## The balls per shot the bonus layer adds in `figures` (an estimate()).
static func added_return(figures: Dictionary) -> float:
	var tulips: float = figures.get("tulip_return", 0.0)
	var jackpots: float = figures.get("jackpot_return", 0.0)
	return tulips + jackpots


# A spin from its start until the next may begin: the last reel's stop (later on a reach,
# which happens with odds `reach_odds`) and the settling pause.
static func _spin_seconds(reach_odds: float) -> float:
	var last: float = ReelSet.STOP_SECONDS[ReelSet.REELS - 1]
	return last + reach_odds * ReelSet.REACH_EXTRA + ReelSet.SETTLE_SECONDS


static func _shots(tally: AnalysisTally, band: int) -> int:
	if tally == null:
		return 0
	return tally.total_shots() if band < 0 else tally.band_shots[band]


static func _hits(tally: AnalysisTally, band: int, pocket: int) -> int:
	return tally.pocket_hits(pocket) if band < 0 else tally.hits_in_band(band, pocket)
