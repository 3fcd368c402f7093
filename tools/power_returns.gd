extends SceneTree
## The return a player gets by holding the handle at one strength: the handle fires each
## ball at its set strength plus or minus LaunchHandle.JITTER, so for each strength P
## (every STEP from 0 to 100) this runs the play analysis over P - JITTER .. P + JITTER
## (clamped to 0..100; every power level of the window once, the bonus layer's estimate
## included as in --analyze) and prints one JSON line: the board, the return at uniform
## power (0..100), the best strength and its return, and every window's return.
##   tools/godot.sh --headless --path . -s res://tools/power_returns.gd -- --board=fever
##   [--step=2] [--shots=400] [--threads=2]


func _initialize() -> void:
	var args := {"board": "classic", "step": "2", "shots": "400", "threads": "2"}
	for arg in OS.get_cmdline_user_args():
		var parts := arg.trim_prefix("--").split("=", true, 1)
		args[parts[0]] = parts[1] if parts.size() > 1 else "yes"
	var path := "res://levels/pachinko/%s.board" % args["board"]
	var loaded := BoardLoader.load_board(path)
	if loaded.level == null:
		printerr("power_returns: %s" % loaded.error)
		quit(2)
		return
	var step := float(args["step"])
	var shots := int(args["shots"])
	var threads := int(args["threads"])
	var windows: Array[Dictionary] = []
	var best := {"power": -1.0, "return": -1.0}
	var centre := 0.0
	while centre <= 100.0 + 0.001:
		var window := _window_return(
			loaded.level,
			maxf(centre - LaunchHandle.JITTER, 0.0),
			minf(centre + LaunchHandle.JITTER, 100.0),
			shots,
			threads
		)
		window["power"] = centre
		windows.append(window)
		var ret := float(window["return"])
		if ret > float(best["return"]):
			best = {"power": centre, "return": ret}
		centre += step
	var report := {
		"board": args["board"],
		"best_power": best["power"],
		"best_return": best["return"],
		"handle_mean": _mean(windows),
		"windows": windows,
	}
	print(JSON.stringify(report))
	quit(0)


# The expected return (bonus layer included) of shots uniform over from..to, with each
# pocket's catch rate and what the bonus layer adds.
static func _window_return(
	level: BoardLevel, from: float, to: float, shots: int, threads: int
) -> Dictionary:
	var plan := AnalysisPlan.create(level, shots, 1)
	plan.threads = threads
	plan.power_from = from
	plan.power_to = to
	var analysis := PachinkoAnalysis.new(plan)
	var tally := analysis.run()
	var open_tally: AnalysisTally = null
	if not level.bonus_pockets.is_empty():
		var open_run := PachinkoAnalysis.new(plan.with_bonus_open())
		open_run.reuse_climbs(analysis.climb_table())
		open_tally = open_run.run()
	var report := AnalysisReport.build(plan, tally, analysis.wall_seconds, open_tally)
	var rates: Array[float] = []
	for pocket: Dictionary in report["pockets"]:
		rates.append(float(pocket["rate"]))
	var total := float(report.get("expected_return", report["return"]))
	return {
		"power": snappedf((from + to) / 2.0, 0.01),
		"return": snappedf(total, 0.001),
		"bonus_added": snappedf(total - float(report["return"]), 0.001),
		"rates": rates,
	}


static func _mean(windows: Array[Dictionary]) -> float:
	var total := 0.0
	for w in windows:
		total += float(w["return"])
	return snappedf(total / maxf(windows.size(), 1.0), 0.001)
