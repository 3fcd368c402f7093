class_name AnalysisReport
extends RefCounted
## Turns the counts of a pachinko analysis into the figures people read: the JSON report
## of `--analyze=pachinko` and the editor's overlay. Plain data (numbers, strings, arrays,
## dictionaries), so it is written and read back as JSON.
##
## return: balls back in the cup per ball shot (a pocket's payout, or 1 for a weak shot
## that rolled back down the rail), so a return of 1.0 or more means the game cannot be
## lost on average.
##
## expected_return (whole run and per band): return plus what the bonus layer adds when
## the rules open its pockets (BonusEstimate, from a second run with them held open: pass
## its tally as `open_tally`). It equals return on a board without a bonus layer, and is
## left out for a bonus board analysed without the open run.

## Report format version (bump when keys change meaning; 3: powers in hundredths, as
## the rules fire them, so reports of the old quarter-point grid are stale; 4: shots played
## among the balls in play at the game's pace, powers drawn without putting them back).
const VERSION := 4
## Rates and figures are rounded to this many decimals.
const DECIMALS := 0.00001


## The report for `tally` from `plan` (wall time `wall_s` seconds).
static func build(
	plan: AnalysisPlan, tally: AnalysisTally, wall_s: float, open_tally: AnalysisTally = null
) -> Dictionary:
	var level := plan.level
	var n := tally.total_shots()
	var value := AnalysisTally.total(tally.band_value)
	var value_sq := AnalysisTally.total(tally.band_value_sq)
	var pockets: Array[Dictionary] = []
	# The level's pockets, then the bonus pockets (with their "role").
	var facts := BonusGeometry.world_pockets(level)
	for p in tally.pocket_count:
		var hits := tally.pocket_hits(p)
		var fact: Dictionary = facts[p] if p < facts.size() else {}
		var at: Vector2 = fact.get("position", Vector2.ZERO)
		(
			pockets
			. append(
				{
					"id": p,
					"role": fact.get("role", "pocket"),
					"payout": fact.get("payout", 0),
					"x": at.x,
					"y": at.y,
					"hits": hits,
					"rate": _round(float(hits) / n if n > 0 else 0.0),
					"ci95": _round(AnalysisStats.rate_half_width(hits, n)),
				}
			)
		)
	var bands: Array[Dictionary] = []
	for b in tally.band_count:
		bands.append(_band(tally, b))
	var dead: Array[int] = []
	for p in AnalysisStats.dead_pockets(tally):
		# An attacker's lid is shut without the rules' jackpots: never counted dead.
		if p >= facts.size() or facts[p]["role"] != "attacker":
			dead.append(p)
	var report := {
		"version": VERSION,
		"game": BoardLevel.PACHINKO_NAME,
		"board": level.board_id,
		"shots": n,
		"seed": plan.rng_seed,
		"threads": plan.threads,
		"played": plan.played,
		"power_from": plan.power_from,
		"power_to": plan.power_to,
		"wall_s": snappedf(wall_s, 0.001),
		"shots_per_s": snappedf(n / wall_s if wall_s > 0.0 else 0.0, 0.1),
		"return": _round(float(value) / n if n > 0 else 0.0),
		"return_ci95": _round(AnalysisStats.mean_half_width(value, value_sq, n)),
		"returned": AnalysisTally.total(tally.band_returned),
		"drained": AnalysisTally.total(tally.band_drained),
		"stuck": AnalysisTally.total(tally.band_stuck),
		"pockets": pockets,
		"bands": bands,
		"dead_pockets": dead,
		"aim_tv": _round(AnalysisStats.aim_distance(tally)),
		"ball_steps": tally.ball_steps,
		"density_cell": AnalysisPlan.DENSITY_CELL,
	}
	_add_expected(report, level, tally, open_tally)
	return report


# expected_return for the run and each band, and the bonus figures behind it.
static func _add_expected(
	report: Dictionary, level: BoardLevel, tally: AnalysisTally, open_tally: AnalysisTally
) -> void:
	var has_bonus := not level.bonus_pockets.is_empty()
	if has_bonus and open_tally == null:
		return
	var bands: Array[Dictionary] = report["bands"]
	for b in bands.size():
		var added := 0.0
		if has_bonus:
			added = BonusEstimate.added_return(BonusEstimate.estimate(level, tally, open_tally, b))
		bands[b]["expected_return"] = _round(number(bands[b]["return"]) + added)
	var whole := BonusEstimate.estimate(level, tally, open_tally) if has_bonus else {}
	if has_bonus:
		var rounded := {}
		for key: String in whole:
			rounded[key] = _round(number(whole[key]))
		report["bonus"] = rounded
	var total := number(report["return"]) + BonusEstimate.added_return(whole)
	report["expected_return"] = _round(total)


## A number read from a report: a JSON number (float once parsed, int when fresh), or
## `fallback` for anything else.
static func number(value: Variant, fallback := 0.0) -> float:
	if value is float:
		return value
	if value is int:
		var whole: int = value
		return float(whole)
	return fallback


static func _band(tally: AnalysisTally, b: int) -> Dictionary:
	var n := tally.band_shots[b]
	var rates: Array[float] = []
	for p in tally.pocket_count:
		rates.append(_round(float(tally.hits_in_band(b, p)) / n if n > 0 else 0.0))
	var span := AnalysisPlan.band_range(b)
	var value := tally.band_value[b]
	var half := AnalysisStats.mean_half_width(value, tally.band_value_sq[b], n)
	return {
		"power_from": span.x,
		"power_to": span.y,
		"shots": n,
		"return": _round(float(value) / n if n > 0 else 0.0),
		"return_ci95": _round(half) if is_finite(half) else -1.0,
		"returned": tally.band_returned[b],
		"pocket_rates": rates,
		"entry_x": _entry(tally, b),
	}


# Where the band's shots first met a pin: median and 10th / 90th percentile of x (-1 when
# none met one).
static func _entry(tally: AnalysisTally, b: int) -> Dictionary:
	return {
		"p10": tally.entry_percentile(b, 0.1),
		"median": tally.entry_percentile(b, 0.5),
		"p90": tally.entry_percentile(b, 0.9),
	}


static func _round(x: float) -> float:
	return snappedf(x, DECIMALS) if is_finite(x) else -1.0
