extends SceneTree
## How long a maze board takes to open, and whether the loading curtain's ring keeps turning
## meanwhile: asks App.start_game as the level select does and notes the time of every drawn
## frame until the board has drawn a few of its own. Prints the seconds from the click to the
## board's first frame and the longest gap between two drawn frames (the ring stands still
## that long). Run by tools/maze_open_time.sh under Xvfb (a real window, software GL).
##   MAZE_OPEN_BOARD=first_roll (the board's file name in levels/maze/)
##   MAZE_OPEN_SHOT=5 (saves the 5th frame drawn after the click as build/look/maze_open_frame.png)

const AppScript := preload("res://scenes/app/app.gd")
const GAME_SCENE := "res://scenes/maze/maze_game.tscn"
const SCRATCH_SETTINGS := "user://open_time_settings.cfg"
const SCRATCH_SAVE := "user://open_time_save.cfg"
## Frames the board draws before the measurement ends.
const BOARD_FRAMES := 3
## Give up after this many seconds.
const LIMIT_S := 60.0

var _drawn := PackedFloat64Array()


func _initialize() -> void:
	_run.call_deferred()


func _run() -> void:
	var app := root.get_node("/root/App") as AppScript
	app.load_player_files(SCRATCH_SETTINGS, SCRATCH_SAVE)
	var board := OS.get_environment("MAZE_OPEN_BOARD")
	if board.is_empty():
		board = "first_roll"
	var path := "res://levels/maze/%s.board" % board
	# a few frames of the menu-less window first, as after the level select
	for i in 5:
		await process_frame
	RenderingServer.frame_post_draw.connect(_on_drawn)
	var start := Time.get_ticks_usec()
	app.start_game(BoardLevel.MAZE_NAME, path)
	var opened_at := -1.0
	var board_frames := 0
	while (Time.get_ticks_usec() - start) * 1e-6 < LIMIT_S:
		await RenderingServer.frame_post_draw
		var scene := current_scene
		if scene != null and scene.scene_file_path == GAME_SCENE and not app.curtain.is_covering():
			if opened_at < 0.0:
				opened_at = (Time.get_ticks_usec() - start) * 1e-6
			board_frames += 1
			if board_frames >= BOARD_FRAMES:
				break
	RenderingServer.frame_post_draw.disconnect(_on_drawn)
	if opened_at < 0.0:
		printerr("maze_open_time: %s did not open within %.0f s" % [board, LIMIT_S])
		quit(1)
		return
	var longest := 0.0
	var previous := float(start)
	var gaps := PackedStringArray()
	for at in _drawn:
		var gap := (at - previous) * 1e-6
		longest = maxf(longest, gap)
		gaps.append("%.2f" % gap)
		previous = at
	print("maze_open_time: seconds between drawn frames: ", " ".join(gaps))
	print(
		(
			(
				"maze_open_time: %s: board drawn %.2f s after the click; %d frames drawn"
				+ " meanwhile, longest gap %.2f s"
			)
			% [board, opened_at, _drawn.size(), longest]
		)
	)
	quit(0)


func _on_drawn() -> void:
	_drawn.append(float(Time.get_ticks_usec()))
	# MAZE_OPEN_SHOT=N saves the Nth frame drawn after the click, to see the curtain at work
	if str(_drawn.size()) == OS.get_environment("MAZE_OPEN_SHOT"):
		var folder := ProjectSettings.globalize_path("res://build/look")
		DirAccess.make_dir_recursive_absolute(folder)
		root.get_texture().get_image().save_png(folder + "/maze_open_frame.png")
