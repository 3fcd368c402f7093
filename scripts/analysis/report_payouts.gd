class_name ReportPayouts
extends RefCounted
## A pachinko analysis report priced with other payouts. A payout changes what a catch is
## worth, never where a ball goes: the report's catch counts stay true, and the return, its
## confidence interval and each band's return follow from the counts and the new payouts
## alone, with no new shots. The analysis cache keys results by the board without its
## payouts (geometry_text), so a payout-only edit finds the stored counts and this prices
## them at once.
##
## Every shot is worth one thing: a catch pays its pocket's payout, a shot that rolled back
## down the rail gives its ball back (1), anything else 0. So the sum of the values is
## Σ hits·payout + returned and the sum of their squares Σ hits·payout² + returned, exactly
## the figures AnalysisTally keeps.


## The board's text with every payout left out (set to 0): what the analysis's counts
## depend on (AnalysisCache's key).
static func geometry_text(level: BoardLevel) -> String:
	var copy := level.duplicate_level()
	for spec in copy.pockets:
		if spec != null:
			spec.payout = 0
	for spec in copy.bonus_pockets:
		if spec != null:
			spec.payout = 0
	return BoardTextWriter.play_text(copy)


## The payout of every pocket the analysis counts, by report pocket id (the level's
## pockets, then its bonus pockets: BonusGeometry.world_pockets).
static func payouts_of(level: BoardLevel) -> PackedInt32Array:
	var payouts := PackedInt32Array()
	for fact: Dictionary in BonusGeometry.world_pockets(level):
		var payout: int = fact["payout"]
		payouts.append(payout)
	return payouts


## `report` (AnalysisReport.build, maybe read back from JSON) with `level`'s payouts: each
## pocket's payout, the return and its 95% interval, every band's return. The bonus
## estimate needs the open run's counts, which a report does not keep, so a repriced
## report of a bonus board leaves it out; a plain board's expected return is its return.
## The report itself is not changed; {} stays {}.
static func repriced(report: Dictionary, level: BoardLevel) -> Dictionary:
	if report.is_empty() or level == null:
		return report
	var payouts := payouts_of(level)
	var out := report.duplicate(true)
	var pockets: Array = out.get("pockets", [])
	if pockets.size() != payouts.size():
		return {}  # counted on another set of pockets: these counts say nothing here
	var changed := false
	for p in pockets.size():
		var pocket: Dictionary = pockets[p]
		changed = changed or roundi(AnalysisReport.number(pocket.get("payout"))) != payouts[p]
		pocket["payout"] = payouts[p]
	if not changed:
		return report
	var n := roundi(AnalysisReport.number(out.get("shots")))
	var returned := roundi(AnalysisReport.number(out.get("returned")))
	var hits := PackedInt64Array()
	for pocket: Dictionary in pockets:
		hits.append(roundi(AnalysisReport.number(pocket.get("hits"))))
	_price(out, hits, payouts, n, returned)
	for band: Dictionary in out.get("bands", []):
		var band_n := roundi(AnalysisReport.number(band.get("shots")))
		var band_hits := PackedInt64Array()
		for rate: Variant in band.get("pocket_rates", []):
			band_hits.append(roundi(AnalysisReport.number(rate) * band_n))
		var band_back := roundi(AnalysisReport.number(band.get("returned")))
		_price(band, band_hits, payouts, band_n, band_back)
	out.erase("bonus")
	out.erase("expected_return")
	if level.bonus_pockets.is_empty():
		out["expected_return"] = out["return"]
		for band: Dictionary in out.get("bands", []):
			band["expected_return"] = band["return"]
	else:
		for band: Dictionary in out.get("bands", []):
			band.erase("expected_return")
	return out


# Sets "return" and "return_ci95" of `figures` from catch counts priced at `payouts`.
static func _price(
	figures: Dictionary, hits: PackedInt64Array, payouts: PackedInt32Array, n: int, returned: int
) -> void:
	var value := returned
	var value_sq := returned
	for p in mini(hits.size(), payouts.size()):
		value += hits[p] * payouts[p]
		value_sq += hits[p] * payouts[p] * payouts[p]
	var half := AnalysisStats.mean_half_width(value, value_sq, n)
	figures["return"] = snappedf(float(value) / n, AnalysisReport.DECIMALS) if n > 0 else 0.0
	figures["return_ci95"] = snappedf(half, AnalysisReport.DECIMALS) if is_finite(half) else -1.0
