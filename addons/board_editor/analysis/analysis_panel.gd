@tool
extends VBoxContainer
## The dock's play-analysis section: Analyze fires AnalysisPlan.EDITOR_SHOTS shots at the
## board on worker threads of the editor (PachinkoAnalysis), on more than two cores over
## one worker process per core (AnalysisWorkerPool: the game binary headless), or with
## `use_worker` in one worker process (AnalysisWorker, on every core), while the
## editor stays responsive, with a progress bar and Cancel; the figures and the heat map
## update as chunks of shots finish.
## A finished run is cached per board content (AnalysisCache), so reopening a board, or
## undoing back to an analysed state, shows its figures at once. The overlay itself is
## drawn by analysis_overlay_draw.gd when the plugin calls draw_over().
##
## Under the figures, the balance table (BalanceTable): every paying item's rate, payout
## and share of the return, beside the shares of the result shown before. The cache keeps
## counts by the board without its payouts, so a payout edit shows the new return at once
## (ReportPayouts), with no new shots.

## The overlay should be redrawn (new figures, or none to show).
signal redraw_needed
## A run finished or the shown result changed: the board's problem list may change.
signal results_changed
## A line of the balance table was clicked: select `item` on the board.
signal item_picked(item: Vector2i)

const AnalysisOverlayDraw := preload("res://addons/board_editor/analysis/analysis_overlay_draw.gd")
const AnalysisControls := preload("res://addons/board_editor/analysis/analysis_controls.gd")
const BalanceRows := preload("res://addons/board_editor/analysis/balance_rows.gd")
const BalanceTable := preload("res://addons/board_editor/analysis/balance_table.gd")
const RunProgress := preload("res://addons/board_editor/analysis/run_progress.gd")
## Partial figures are refreshed at most this often while a run goes on, ms.
const UPDATE_MS := 400

## Shots a run fires (tests fire fewer).
var shots := AnalysisPlan.EDITOR_SHOTS
## True runs the analysis in a worker process when one can start (AnalysisWorker.available);
## false, or a worker that fails, runs it on the editor's own threads. Off: measured in the
## editor (tools/editor_analysis_shot.sh, Classic, 10000 shots, 2 cores shared with other
## work, load 8-12), the editor's threads took 33.7-41.0 s drawing every frame and 43.6 s
## idle, the worker 83.5 s and 48.8 s (the headless command line: 30.0 s); the editor's
## threads no longer lag since the physics stopped looking its ball fields up by name.
var use_worker := false
## Worker processes the analysis is split over (AnalysisWorkerPool, the command line's
## `--workers` route); 0 leaves the choice to `use_worker`. By default one per core on more
## than two cores, none on two (where the editor's threads won: see use_worker).
var worker_processes := AnalysisWorkerPool.default_workers()

var _level: BoardLevel
var _key := ""
var _report: Dictionary = {}
var _heat: ImageTexture
## The run: a PachinkoAnalysis here, or an AnalysisWorker (the same interface).
var _run: PachinkoAnalysis
var _run_key := ""
var _run_level: BoardLevel
var _run_started := 0
var _last_update := 0
var _shown_shots := -1

var _controls: AnalysisControls
var _table: BalanceTable
# The balance rows of the figures shown, and of the last other figures shown before them.
var _rows: Array[BalanceRows.Row] = []
var _before_rows: Array[BalanceRows.Row] = []
var _before_return := NAN
# Board (its instance id) -> [before rows, before return] of the boards not shown now: a
# scene tab switched away and back keeps its "(before: 1.21)".
var _kept_before := {}


func _init() -> void:
	name = "PlayAnalysis"
	var tip := (
		"Fire %d shots at random power on worker threads: heat map, pocket rates, aim map" % shots
	)
	_controls = AnalysisControls.new(self, tip, start, cancel, _on_show_toggled)
	_table = BalanceTable.new()
	_table.item_picked.connect(func(item: Vector2i) -> void: item_picked.emit(item))
	add_child(_table)
	set_process(false)


## Shows the analysis of `level` (null or a maze: the section hides). Called after every
## edit: a changed board shows its cached figures, or none; a payout edit reprices them.
func bind(level: BoardLevel) -> void:
	visible = level != null and level.is_pachinko()
	var shown := level if visible else null
	if shown != _level:
		_switch_board(shown)
	_level = shown
	var key := AnalysisCache.key_for(_plan_for(_level)) if _level != null else ""
	if key == _key:
		if not _report.is_empty():
			_show_report(ReportPayouts.repriced(_report, _level), _heat)
		return
	_key = key
	if _run != null and _run_key == key:
		return  # the running analysis is of this very content: keep its partial figures
	var stored := AnalysisCache.load_report(key) if not key.is_empty() else {}
	var image := AnalysisCache.load_heatmap(key) if not stored.is_empty() else null
	var heat := ImageTexture.create_from_image(image) if image != null else null
	_show_report(ReportPayouts.repriced(stored, _level), heat)
	if _run == null:
		_say_result()  # new content with no figures, like the old: "Not analysed..."


# Another board is shown (a scene tab switched, the board deselected): the figures before of
# the board leaving are kept for its return, and the coming board's own come back. Its
# figures are shown afresh: they never become the coming board's "before".
func _switch_board(coming: BoardLevel) -> void:
	if _level != null:
		_kept_before[_level.get_instance_id()] = [_before_rows, _before_return]
	var kept: Array = _kept_before.get(coming.get_instance_id(), []) if coming != null else []
	var rows: Array[BalanceRows.Row] = []
	_before_rows = kept[0] if not kept.is_empty() else rows
	_before_return = kept[1] if not kept.is_empty() else NAN
	_report = {}
	_rows = []


func _notification(what: int) -> void:
	# The dock is going away (the editor closes, the plugin is turned off): no worker
	# process outlives it.
	if what == NOTIFICATION_PREDELETE and _run != null:
		_run.cancel()


## Starts an analysis of the bound board (a snapshot of it: edits during the run do not
## reach the worker threads).
func start() -> void:
	if _level == null or _run != null:
		return
	_run_level = _level.duplicate_level()
	var plan := _plan_for(_run_level)
	plan.threads = OS.get_processor_count()
	_run_key = _key
	var worker_failure := ""
	_run = null
	if worker_processes > 0 and AnalysisWorker.available():
		var pool := AnalysisWorkerPool.new(plan)
		pool.workers = worker_processes
		_run = pool
		if not _run.start():
			worker_failure = pool.failure
			_run = null
	elif use_worker and AnalysisWorker.available():
		_run = AnalysisWorker.new(plan)
		if not _run.start():
			worker_failure = (_run as AnalysisWorker).failure
			_run = null
	if _run == null:
		_run = PachinkoAnalysis.new(plan)
		if not _run.start():
			_controls.status.text = "This board cannot be analysed: %s." % plan.problem()
			_run = null
			return
	_run_started = Time.get_ticks_msec()
	_shown_shots = -1
	if not _report.is_empty():  # what the run's figures will be compared with
		_before_rows = _rows
		_before_return = AnalysisReport.number(_report.get("return"))
	_controls.show_running(_climbing_text())
	if not worker_failure.is_empty():
		push_warning(
			"Play analysis: no worker process (%s); running in the editor" % worker_failure
		)
	set_process(true)


## Stops the running analysis; the shots finished so far stay on the board.
func cancel() -> void:
	if _run != null:
		_run.cancel()


## True while an analysis runs.
func is_running() -> bool:
	return _run != null


## The running analysis: a PachinkoAnalysis, an AnalysisWorker or an AnalysisWorkerPool
## (null when none runs).
func running() -> PachinkoAnalysis:
	return _run


## The figures shown (an AnalysisReport dictionary; empty when none).
func report() -> Dictionary:
	return _report


## The balance table under the figures.
func balance_table() -> BalanceTable:
	return _table


## The return of the figures shown before the current ones (NAN: none yet).
func return_before() -> float:
	return _before_return


## Draws the figures over the board (the plugin calls it from its viewport overlay).
func draw_over(canvas: Control, to_screen: Transform2D) -> void:
	if _level != null and _controls.show.button_pressed and (_run == null or _run_key == _key):
		AnalysisOverlayDraw.draw(canvas, to_screen, _level, _report, _heat)


func _process(_delta: float) -> void:
	if _run == null:
		set_process(false)
		return
	var done := _run.poll()
	_controls.progress.value = run_share()
	if done and _worker_failed():
		_run_here_instead()
	elif done:
		_finish()
	elif Time.get_ticks_msec() - _last_update >= UPDATE_MS:
		_last_update = Time.get_ticks_msec()
		if _run.phase == PachinkoAnalysis.Phase.CLIMBS:
			_controls.status.text = _climbing_text()
		_show_partial(false)


## The share of the running analysis done, climbs and shots together (RunProgress); 0 when
## none runs.
func run_share() -> float:
	if _run == null:
		return 0.0
	return RunProgress.pachinko_share(_run.climb_progress(), _run.progress())


# "Climbing the rail at every power: 3 % done, about 45 s left."
func _climbing_text() -> String:
	return RunProgress.line("Climbing the rail at every power", run_share(), _run_seconds())


# Seconds since the run started.
func _run_seconds() -> float:
	return (Time.get_ticks_msec() - _run_started) / 1000.0


# True when the run was a worker that stopped without its counts (not a cancel).
func _worker_failed() -> bool:
	return _run is AnalysisWorker and not (_run as AnalysisWorker).failure.is_empty()


# The worker failed: the same plan again on the editor's threads (the shots so far are
# dropped: the new run starts over and gives the whole run's figures).
func _run_here_instead() -> void:
	var failure := (_run as AnalysisWorker).failure
	push_warning("Play analysis: %s; running in the editor instead" % failure)
	_run = PachinkoAnalysis.new(_run.plan)
	if not _run.start():
		_run = null
		_controls.show_idle()
		set_process(false)
		_controls.status.text = "The analysis failed: %s." % failure
		return
	_run_started = Time.get_ticks_msec()
	_shown_shots = -1


# Rebuilds the figures and heat map from the chunks finished so far; `final` ones (the
# whole run) go into the cache.
func _show_partial(final: bool) -> void:
	var tally := _run.tally()
	if tally == null or (tally.total_shots() == _shown_shots and not final):
		return
	_shown_shots = tally.total_shots()
	var seconds := (Time.get_ticks_msec() - _run_started) / 1000.0
	var fresh := AnalysisReport.build(_run.plan, tally, seconds)
	var image := HeatmapImage.render_overlay(tally)
	if _run_key == _key:
		# Payouts edited during the run price the counts so far at once.
		var heat := ImageTexture.create_from_image(image)
		_show_report(ReportPayouts.repriced(fresh, _level), heat, true)
	var doing := "%d of %d shots fired" % [_shown_shots, _run.plan.shots]
	_controls.status.text = RunProgress.line(doing, run_share(), seconds)
	if final:
		var saved := AnalysisCache.save(_run_key, fresh, image)
		if saved != OK:
			push_warning("Play analysis: could not cache the result (%s)" % error_string(saved))


func _finish() -> void:
	var cancelled := _run.phase == PachinkoAnalysis.Phase.CANCELLED
	_show_partial(not cancelled)
	var seconds := (Time.get_ticks_msec() - _run_started) / 1000.0
	_run = null
	_controls.show_idle()
	set_process(false)
	if cancelled:
		_controls.status.text = (
			"Cancelled: the figures are from the %d shots done." % maxi(_shown_shots, 0)
		)
	else:
		_say_result()
		_controls.status.text += "\n%d shots in %.1f s." % [shots, seconds]
	redraw_needed.emit()
	results_changed.emit()


func _say_result() -> void:
	if _report.is_empty():
		_controls.status.text = "Not analysed since the last edit." if _level != null else ""
		return
	var dead: Array = _report.get("dead_pockets", [])
	var before := "" if is_nan(_before_return) else " (before: %.2f)" % _before_return
	_controls.status.text = (
		"Return %.2f ± %.2f balls per ball%s; %s."
		% [
			AnalysisReport.number(_report.get("return", 0.0)),
			AnalysisReport.number(_report.get("return_ci95", 0.0)),
			before,
			"no dead pockets" if dead.is_empty() else "%d dead pocket(s)" % dead.size(),
		]
	)


# Shows `report` and `heat`. When they replace other figures, those become the "before"
# of the balance table; figures giving way to none stay the "before" of the next ones.
# `keep_before`: a run's partial figures replace each other, not the figures before the run.
func _show_report(figures: Dictionary, heat: ImageTexture, keep_before := false) -> void:
	var same := figures == _report
	if not same and not _report.is_empty() and not keep_before:
		_before_rows = _rows
		_before_return = AnalysisReport.number(_report.get("return"))
	_report = figures
	_heat = heat
	_rows = BalanceRows.rows(_report, _level)
	_table.show_rows(_rows, _before_rows)
	if same:
		return  # keeps a status such as "Cancelled: ..." in place
	if _run == null:
		_say_result()
	redraw_needed.emit()
	if not keep_before:
		results_changed.emit()  # a run's end says it once for all its partial figures


func _plan_for(level: BoardLevel) -> AnalysisPlan:
	return AnalysisPlan.create(level, shots, 1)


func _on_show_toggled(_on: bool) -> void:
	redraw_needed.emit()
