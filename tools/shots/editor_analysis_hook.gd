@tool
extends Node
## Screenshot hook for tools/editor_analysis_shot.sh. When the editor starts with
## BOARD_EDITOR_ANALYSIS_SHOT="<scene.tscn>;<out.png>" it opens the scene, selects its
## BoardNode, presses Analyze in the board dock (the maze section on a maze board), waits
## for the run to finish (the editor keeps drawing meanwhile), saves the editor window as a
## PNG and quits.

const ENV := "BOARD_EDITOR_ANALYSIS_SHOT"
const ShotCapture := preload("res://tools/shots/shot_capture.gd")
const EditorShotHook := preload("res://tools/shots/editor_shot_hook.gd")
const BoardEditorPlugin := preload("res://addons/board_editor/plugin.gd")
const BoardDock := preload("res://addons/board_editor/ui/board_dock.gd")
## Longest wait for the analysis, seconds.
const RUN_LIMIT := 200.0

var _plugin: BoardEditorPlugin


func _init(plugin: EditorPlugin) -> void:
	_plugin = plugin as BoardEditorPlugin


func _ready() -> void:
	_run.call_deferred()


func _run() -> void:
	var parts := OS.get_environment(ENV).split(";")
	if parts.size() != 2:
		push_error("%s must be '<scene>;<png>', got '%s'." % [ENV, ";".join(parts)])
		get_tree().quit(1)
		return
	OS.low_processor_usage_mode = false
	get_tree().create_timer(RUN_LIMIT + 60.0).timeout.connect(get_tree().quit.bind(1))
	await _frames(60)
	var node := await EditorShotHook.open_board(get_tree(), parts[0])
	if node == null:
		get_tree().quit(1)
		return
	var framer := EditorShotHook.new(_plugin)
	framer.frame_board(node)
	framer.free()
	var dock := _plugin.get_dock()
	var is_maze := node.level != null and node.level.is_maze()
	# EDITOR_ANALYSIS_IDLE_EDITOR=1 times the run in an editor that draws only what changes
	# (its own default low-processor mode), as a designer's does, not one that draws every
	# frame; the picture is taken with every frame drawn again.
	var idle_editor := OS.get_environment("EDITOR_ANALYSIS_IDLE_EDITOR") == "1"
	OS.low_processor_usage_mode = idle_editor
	# EDITOR_ANALYSIS_WORKER=1 / 0 runs it in a worker process / on the editor's threads
	# (unset: the panel's default), to time the two side by side.
	var worker := OS.get_environment("EDITOR_ANALYSIS_WORKER")
	if not is_maze and worker in ["0", "1"]:
		dock.analysis.use_worker = worker == "1"
	# EDITOR_ANALYSIS_POOL=N splits it over N worker processes and the editor itself
	# (AnalysisWorkerPool); 0 leaves it to use_worker.
	var pool := OS.get_environment("EDITOR_ANALYSIS_POOL")
	if not is_maze and pool.is_valid_int():
		dock.analysis.worker_processes = clampi(int(pool), 0, 64)
	if is_maze:
		dock.maze_analysis.start()
	else:
		dock.analysis.start()
	var started := Time.get_ticks_msec()
	while _is_running(dock, is_maze) and Time.get_ticks_msec() - started < RUN_LIMIT * 1000.0:
		await _frames(10)
	print(
		(
			"Analysis shot: run took %.1f s%s%s"
			% [
				(Time.get_ticks_msec() - started) / 1000.0,
				" (idle editor)" if idle_editor else "",
				_run_where(dock, is_maze),
			]
		)
	)
	OS.low_processor_usage_mode = false
	var window := EditorInterface.get_base_control().get_viewport()
	var error: Error = await ShotCapture.save(window, parts[1])
	get_tree().quit(0 if error == OK else 1)


func _frames(count: int) -> void:
	for i in count:
		await get_tree().process_frame


func _is_running(dock: BoardDock, is_maze: bool) -> bool:
	return dock.maze_analysis.is_running() if is_maze else dock.analysis.is_running()


# Where the analysis ran, for the log line.
func _run_where(dock: BoardDock, is_maze: bool) -> String:
	if not is_maze and dock.analysis.worker_processes > 0:
		return " (%d worker processes and the editor)" % dock.analysis.worker_processes
	if not is_maze and dock.analysis.use_worker:
		return " (worker process)"
	return " (editor threads)"
