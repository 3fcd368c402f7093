extends GutTest
## The shipped pachinko boards stay balanced, measured as the issue measures them: the play
## analysis at uniform random power (here fewer shots than the 10000 of the release check,
## with a fixed seed, so each test takes a few seconds and always gives the same figures).
## Every pocket catches something, power aims (weakest vs strongest fifth), and the return,
## with the bonus layer's tulips and jackpots on the bonus boards, stays between 0.6 and
## 0.95.

const SHOTS := 2000
const BONUS_SHOTS := 1000
const SEED := 17
const RETURN_LOW := 0.6
const RETURN_HIGH := 0.95


func _report(board: String, shots: int) -> Dictionary:
	var level := BoardLoader.load_board("res://levels/pachinko/%s.board" % board).level
	assert_not_null(level, "%s loads" % board)
	if level == null:
		return {}
	var plan := AnalysisPlan.create(level, shots, SEED)
	plan.threads = 2
	var tally := PachinkoAnalysis.new(plan).run()
	var open: AnalysisTally = null
	if not level.bonus_pockets.is_empty():
		open = PachinkoAnalysis.new(plan.with_bonus_open()).run()
	return AnalysisReport.build(plan, tally, 1.0, open)


func _assert_balanced(board: String, shots: int) -> Dictionary:
	var report := _report(board, shots)
	if report.is_empty():
		return report
	for pocket: Dictionary in report["pockets"]:
		if pocket["role"] != "attacker":
			assert_gt(pocket["hits"], 0, "%s: pocket %d catches" % [board, pocket["id"]])
	assert_gte(report["aim_tv"], 0.3, "%s: power aims" % board)
	var ret: float = report["expected_return"]
	assert_between(ret, RETURN_LOW, RETURN_HIGH, "%s: return at random power" % board)
	gut.p(
		"%s: return %.3f expected %.3f aim %.3f" % [board, report["return"], ret, report["aim_tv"]]
	)
	return report


func test_classic_is_balanced() -> void:
	_assert_balanced("classic", SHOTS)


func test_tulips_is_balanced() -> void:
	_assert_balanced("tulips", SHOTS)


func test_windmills_is_balanced_and_a_good_aim_wins() -> void:
	var report := _assert_balanced("windmills", SHOTS)
	var best := 0.0
	for band: Dictionary in report.get("bands", []):
		best = maxf(best, band["return"])
	assert_gte(best, 1.0, "the best fifth of power returns a ball or more per ball")


func test_fever_is_balanced_with_its_jackpots() -> void:
	var report := _assert_balanced("fever", BONUS_SHOTS)
	assert_gt(report.get("bonus", {}).get("jackpots_per_1000", 0.0), 0.0)


func test_hanami_is_balanced_with_its_jackpots() -> void:
	var report := _assert_balanced("hanami", BONUS_SHOTS)
	assert_gt(report.get("bonus", {}).get("jackpots_per_1000", 0.0), 0.0)
