class_name PachinkoAnalyzeCli
extends RefCounted
## The pachinko report of the `--analyze` command (AnalyzeCli): fires the plan's shots on
## `--workers` worker processes (AnalysisWorkerPool) or on threads here, again with the
## bonus pockets held open when the board has any (BonusEstimate), then builds the report
## and writes its heat-map PNG (with `--profile`, the run's timings go in too).


## The report of `plan` on the board at `board_path`, its heat map written to
## `abs_base`.png and named `base`.png; {"error": why} for flags or a plan that cannot run,
## with "unwritten": true when the PNG could not be written. `values` are the command's
## flags (workers, profile).
static func report(
	plan: AnalysisPlan, values: Dictionary, board_path: String, base: String, abs_base: String
) -> Dictionary:
	var workers: int = values.get("workers", AnalysisWorkerPool.default_workers())
	if workers < 0 or workers > 64:
		return {"error": "--workers must be 0 to 64 (got %d)" % workers}
	if workers > 0 and values.get("profile", false):
		if values.has("workers"):
			return {"error": "--profile times this process: use --workers=0"}
		workers = 0
	var analysis: PachinkoAnalysis
	var tally: AnalysisTally = null
	var open_tally: AnalysisTally = null
	var bonus := not plan.level.bonus_pockets.is_empty()
	if workers > 0:
		var pool := AnalysisWorkerPool.new(plan)
		pool.workers = workers
		pool.with_open = bonus
		pool.board_path = board_path
		analysis = pool
		tally = pool.run()
		open_tally = pool.open_tally()
		if tally == null:
			printerr("analyze: the workers could not start (%s); running here" % pool.failure)
	if tally == null:
		analysis = PachinkoAnalysis.new(plan)
		if values.get("profile", false):
			analysis.profile = AnalysisProfile.new()
		tally = analysis.run()
		if tally == null:
			return {"error": plan.problem()}
		if bonus:
			# The same shots again with the bonus pockets held open, for BonusEstimate.
			# Its rail climbs are the first run's (the climb world keeps the bonus parts
			# shut).
			var open_run := PachinkoAnalysis.new(plan.with_bonus_open())
			open_run.reuse_climbs(analysis.climb_table())
			open_tally = open_run.run()
	var mark := Time.get_ticks_usec()
	var made := AnalysisReport.build(plan, tally, analysis.wall_seconds, open_tally)
	made["heatmap"] = base + ".png"
	var png_error := HeatmapImage.render(plan.level, tally).save_png(abs_base + ".png")
	if analysis.profile != null:
		made["profile"] = analysis.profile.to_dict()
		made["profile"]["report_and_heatmap_s"] = snappedf(
			(Time.get_ticks_usec() - mark) / 1e6, 0.001
		)
	if png_error != OK:
		var problem := "could not write %s (%s)" % [base + ".png", error_string(png_error)]
		return {"error": problem, "unwritten": true}
	return made
