extends SceneTree
## Every shipped maze board (or those named with --boards=a,b) at rest and at full tilt, in
## the window size it is run at, saved to build/look/boards/<board>_<w>x<h>_rest.png and
## _tilt.png (tilted down and right, all the way). tools/maze_board_shots.sh runs it under
## Xvfb at 1280x720, 900x700 and 720x1280. Scratch settings and saves, never the player's.

const ShotCapture := preload("res://tools/shots/shot_capture.gd")
const ScreenOpener := preload("res://tools/shots/screen_opener.gd")
const GAME_SCENE := "res://scenes/maze/maze_game.tscn"
const OUT_DIR := "res://build/look/boards"
const SCRATCH_SETTINGS := "user://board_shots_settings.cfg"
const SCRATCH_SAVE := "user://board_shots_save.cfg"


func _initialize() -> void:
	_run.call_deferred()


func _run() -> void:
	for scratch in [SCRATCH_SETTINGS, SCRATCH_SAVE]:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(scratch))
	var app := root.get_node("/root/App")
	app.call("load_player_files", SCRATCH_SETTINGS, SCRATCH_SAVE)
	var window := DisplayServer.window_get_size()
	var tag := "%dx%d" % [window.x, window.y]
	var failed := 0
	for board in _boards():
		var path := "res://levels/maze/%s.board" % board
		var open := app.get("start_game") as Callable
		var game := await ScreenOpener.open(self, open.bind(BoardLevel.MAZE_NAME, path), GAME_SCENE)
		if game == null:
			failed += 1
			continue
		var error: Error = await ShotCapture.save(root, "%s/%s_%s_rest.png" % [OUT_DIR, board, tag])
		for action: StringName in [&"tilt_right", &"tilt_down"]:
			Input.action_press(action, 1.0)
		for frame in 90:  # the board eases to full tilt
			await process_frame
		error = maxi(
			error, await ShotCapture.save(root, "%s/%s_%s_tilt.png" % [OUT_DIR, board, tag])
		)
		for action: StringName in [&"tilt_right", &"tilt_down"]:
			Input.action_release(action)
		failed += int(error != OK)
	quit(1 if failed > 0 else 0)


func _boards() -> PackedStringArray:
	for arg in OS.get_cmdline_user_args():
		if arg.begins_with("--boards="):
			return arg.trim_prefix("--boards=").split(",")
	var out := PackedStringArray()
	for file in DirAccess.get_files_at("res://levels/maze"):
		if file.ends_with(".board"):
			out.append(file.get_basename())
	out.sort()
	return out
