@tool
extends VBoxContainer
## The dock's play-analysis section for maze boards: Analyze lets the autoplay pilot play
## the board (MazeAnalysis: RUNS games in easy and RUNS in hard mode) on worker threads while
## the editor stays responsive, with a progress bar and Cancel. A hopeless game is given up
## within seconds (a ball trapped, or no progress for 20 s). The result (solve rate and
## median time per mode; where and why games were lost, in words by maze_loss_words.gd and
## drawn by maze_loss_draw.gd) shows in the dock and over the board; it is kept per board
## content (BoardTextWriter.play_hash: names left out), in memory and in user://analysis/
## like pachinko's, so a rename, "Save board as", an undo back to an analysed board or the
## next editor session shows its figures again.

## The overlay should be redrawn (new figures, or none to show).
signal redraw_needed

const MazeAnalysisDraw := preload("res://addons/board_editor/analysis/maze_analysis_draw.gd")
const AnalysisControls := preload("res://addons/board_editor/analysis/analysis_controls.gd")
const MazeLossWords := preload("res://addons/board_editor/analysis/maze_loss_words.gd")
const RunProgress := preload("res://addons/board_editor/analysis/run_progress.gd")
## First seed of the games: the same board always gives the same figures.
const SEED := 1

## Games per mode a run plays (tests play fewer).
var runs := 6

# Board content hash -> report, for this editor session.
var _results := {}
var _level: BoardLevel
var _key := ""
var _report: Dictionary = {}
var _run: MazeAnalysis
var _run_key := ""
var _run_level: BoardLevel
var _run_started := 0

var _controls: AnalysisControls


func _init() -> void:
	name = "MazeAnalysis"
	var tip := (
		"Let the autoplay pilot play %d games in easy and %d in hard mode: solve rates, times, "
		+ "and where and why games were lost (a ball trapped or stuck, a hole, time ran out)."
	)
	_controls = AnalysisControls.new(self, tip, start, cancel, _on_show_toggled)
	set_process(false)


func _ready() -> void:
	_controls.analyze.tooltip_text = _controls.analyze.tooltip_text % [runs, runs]


## Shows the analysis of `level` (null or a pachinko board: the section hides). Called after
## every edit: a changed board shows the figures of that very content, or none.
func bind(level: BoardLevel) -> void:
	visible = level != null and level.is_maze()
	_level = level if visible else null
	var key := BoardTextWriter.play_hash(_level) if _level != null else ""
	if key == _key:
		return
	_key = key
	if not key.is_empty() and not _results.has(key):
		var stored := AnalysisCache.load_maze(key)  # analysed in an earlier session
		# A report from before the loss reasons says too little: analyse again.
		if stored.get("maze_version", 1.0) == float(MazeAnalysis.MAZE_VERSION):
			_results[key] = stored
	_report = _results.get(key, {})
	_say_result()
	redraw_needed.emit()


## Starts an analysis of a snapshot of the bound board (edits during the run do not reach
## the games). A board the board check proves unwinnable (the goal or a start closed in)
## plays no games: the status says why at once.
func start() -> void:
	if _level == null or _run != null:
		return
	var unwinnable := unwinnable_reason(_level)
	if not unwinnable.is_empty():
		_controls.status.text = "No games played: this board cannot be won. " + unwinnable
		return
	_run_level = _level.duplicate_level()
	_run_key = _key
	_run = MazeAnalysis.create(_run_level, runs, SEED)
	_run.start(OS.get_processor_count())
	_run_started = Time.get_ticks_msec()
	_controls.show_running(_playing_text())
	set_process(true)


## The board check's reason why no ball can be won on `level` (a goal or ball starts closed
## in by walls), or "" when every start can roll to the goal.
static func unwinnable_reason(level: BoardLevel) -> String:
	var reasons := PackedStringArray()
	for issue in BoardValidator.validate(level):
		if issue.kind in ["goal_closed_in", "start_cannot_reach_goal"]:
			reasons.append(issue.message)
	return " ".join(reasons)


## Stops the running analysis at the games' next frame; nothing is kept.
func cancel() -> void:
	if _run != null:
		_run.cancel()


## True while an analysis runs.
func is_running() -> bool:
	return _run != null


## The figures shown (a MazeAnalysis report; empty when none).
func report() -> Dictionary:
	return _report


## Draws the figures over the board (the plugin calls it from its viewport overlay).
func draw_over(canvas: Control, to_screen: Transform2D) -> void:
	if _level != null and _controls.show.button_pressed and not _report.is_empty():
		MazeAnalysisDraw.draw(canvas, to_screen, _level, _report)


func _process(_delta: float) -> void:
	if _run == null:
		set_process(false)
		return
	_controls.progress.value = _run.progress()
	_controls.status.text = _playing_text()
	if _run.poll():
		_finish()


# "The pilot is playing 12 games (3 done): 30 % done, about 35 s left."
func _playing_text() -> String:
	var doing := "The pilot is playing %d games (%d done)" % [_run.games(), _run.games_done()]
	var seconds := (Time.get_ticks_msec() - _run_started) / 1000.0
	return RunProgress.line(doing, _run.progress(), seconds)


func _finish() -> void:
	var cancelled := _run.is_cancelled()
	var finished := _run.report()
	_run = null
	_run_level = null
	_controls.show_idle()
	set_process(false)
	if cancelled:
		_say_result()
		_controls.status.text = "Cancelled: no figures kept.\n" + _controls.status.text
		return
	_results[_run_key] = finished
	var saved := AnalysisCache.save_maze(_run_key, finished)
	if saved != OK:
		push_warning("Maze analysis: could not keep the figures (%s)." % error_string(saved))
	if _run_key == _key:
		_report = finished
	_say_result()
	var games: int = finished["runs"]
	var seconds: float = finished["wall_s"]
	_controls.status.text += "\n%d games in %.1f s." % [games * 2, seconds]
	redraw_needed.emit()


func _exit_tree() -> void:
	if _run != null:
		_run.cancel()
		_run.wait()  # the games stop within a frame of play each
		_run = null


func _say_result() -> void:
	if _report.is_empty():
		_controls.status.text = "Not analysed since the last edit." if _level != null else ""
		return
	var lines := PackedStringArray()
	for mode: String in ["easy", "hard"]:
		var figures: Dictionary = _report[mode]
		lines.append(MazeAnalysisDraw.mode_line(mode, figures))
	lines.append_array(MazeLossWords.lines(_report))
	_controls.status.text = "\n".join(lines)


func _on_show_toggled(_on: bool) -> void:
	redraw_needed.emit()
