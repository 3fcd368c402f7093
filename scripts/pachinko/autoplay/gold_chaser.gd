class_name GoldChaser
extends RefCounted
## The autoplay's gold-chasing pilot: it holds the handle at the strength whose window
## (strength ± LaunchHandle.JITTER) is worth most by the board's PinReach: what its lone
## shots' pockets pay, plus every lit gold pin they touch at a ball and a share of the
## set's prize. It re-aims each time a gold pin goes out (aim_key). While a jackpot's rounds
## last it feeds the attacker instead, at the middle of the band the launcher shows
## (AttackerBands), as a player is told to. `held_best` is the same measure
## without gold pins: the single strength a player who ignores them would hold.

## What the autoplay counts a set's prize as, in balls (a Gold spin: a jackpot in three of
## about 110 balls; a Gold rush: double pay for 20 s at about one catch a second).
const PRIZE_BALLS := 30.0
## What the autoplay counts a jackpot as, in balls (a start pocket's catch is worth a spin:
## this over the reel symbols squared).
const JACKPOT_BALLS := 110.0


## The strength (0..100) the chaser holds now in `rules`' game.
static func strength(rules: PachinkoRules) -> int:
	var band := AttackerBands.band_of(rules.level)
	if rules.bonus.rounds.active() and band != Vector2i.ZERO:
		return floori((band.x + band.y) * 0.5)
	var gold := rules.gold
	if gold.reach == null:
		return held_best(PinReach.of(rules.level))
	var lit := gold.lit_pins()
	var pin_value := 1.0 + PRIZE_BALLS / maxf(lit.size(), 1.0)
	var factor := GoldPins.RUSH_FACTOR if gold.rush_on() else 1
	return _best(gold.reach, lit, pin_value, factor)


## A number that changes whenever the chaser should aim again: a gold pin out, a new set,
## a Gold rush or a jackpot beginning or ending.
static func aim_key(rules: PachinkoRules) -> int:
	var gold := rules.gold
	var moments := int(gold.rush_on()) * 2 + int(rules.bonus.rounds.active())
	return gold.pins_out * 1000 + gold.set_number * 4 + moments


## The strength whose window's pockets pay most, gold pins left out.
static func held_best(reach: PinReach) -> int:
	return _best(reach, PackedInt32Array(), 0.0, 1)


static func _best(reach: PinReach, lit: PackedInt32Array, pin_value: float, factor: int) -> int:
	var best := 0
	var best_value := -1.0
	var jitter := int(LaunchHandle.JITTER)
	for s in 101:
		var total := 0.0
		var shots := 0
		for p in range(maxi(s - jitter, 0), mini(s + jitter, 100) + 1):
			total += reach.payout_at(p) * factor + _spin_value(reach, p)
			for pin in reach.pins_at(p):
				if lit.has(pin):
					total += pin_value
			shots += 1
		if total / shots > best_value:
			best_value = total / shots
			best = s
	return best


# What a start pocket's catch at `power` adds through its spin (0 elsewhere).
static func _spin_value(reach: PinReach, power: int) -> float:
	var level := reach.board()
	var index := BonusGeometry.bonus_index(level, reach.end_at(power)) if level != null else -1
	if index < 0 or level.bonus_pockets[index].role != BonusPocketSpec.Role.START:
		return 0.0
	var symbols := maxf(level.bonus_pockets[index].symbols, 1.0)
	return JACKPOT_BALLS / (symbols * symbols)
