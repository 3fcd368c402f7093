class_name AnalysisWarnings
extends RefCounted
## Turns analysis figures into problems for the board's problem list: dead pockets, a board
## that pays back a ball or more per ball at random power (it cannot be lost), and power
## that does not aim. Reads a finished report only: plain validation never runs an analysis
## (the editor passes AnalysisCache.cached_report(level)).

## Below this distance between the weakest and strongest fifth's catches, power does not aim.
const AIM_MIN_DISTANCE := 0.3
## Return at or above this: the game cannot be lost on average.
const RETURN_LIMIT := 1.0


## The warnings `report` (an AnalysisReport, possibly from the cache) gives for `level`.
static func issues(level: BoardLevel, report: Dictionary) -> Array[BoardIssue]:
	var out: Array[BoardIssue] = []
	if level == null or report.is_empty():
		return out
	var shots := roundi(AnalysisReport.number(report.get("shots"), 0.0))
	var pockets: Array = report.get("pockets", [])
	for dead: Variant in report.get("dead_pockets", []):
		var p := roundi(AnalysisReport.number(dead, -1.0))
		var at := level.pockets[p].position if p >= 0 and p < level.pockets.size() else Vector2()
		var text := "Pocket %d is dead: in %d analysed shots no power reaches it" % [p + 1, shots]
		var bonus := p - level.pockets.size()
		if bonus >= 0 and bonus < level.bonus_pockets.size():
			at = level.bonus_pockets[bonus].position
			var name := BonusChecks.label(level, bonus)
			text = "%s is dead: in %d analysed shots no power reaches it" % [name, shots]
		text += " (under 0.5%% at every power)."
		BoardIssue.add_to(out, BoardIssue.Severity.WARNING, text, at, "analysis_dead_pocket")
	var ret := AnalysisReport.number(report.get("return"), 0.0)
	if ret >= RETURN_LIMIT and not pockets.is_empty():
		var text := (
			"At random power the board pays back %.2f ± %.2f balls per ball"
			% [ret, AnalysisReport.number(report.get("return_ci95"), 0.0)]
		)
		text += ": the game cannot be lost. Lower some payouts."
		BoardIssue.add_to(
			out, BoardIssue.Severity.WARNING, text, level.ring_center, "analysis_return_high"
		)
	var aim := AnalysisReport.number(report.get("aim_tv"), -1.0)
	if aim >= 0.0 and aim < AIM_MIN_DISTANCE:
		var text := "Power does not aim: the weakest and the strongest shots land in the same"
		text += (
			" pockets almost alike (distance %.2f of 1, want %.1f or more)."
			% [aim, AIM_MIN_DISTANCE]
		)
		BoardIssue.add_to(
			out, BoardIssue.Severity.WARNING, text, level.ring_center, "analysis_power_no_aim"
		)
	return out


## The warnings from the cached analysis of `level`'s current content (none when it has
## not been analysed since its last edit).
static func cached_issues(level: BoardLevel) -> Array[BoardIssue]:
	return issues(level, AnalysisCache.cached_report(level))
