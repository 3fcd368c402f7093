@tool
extends RefCounted
## The one capture step of every screenshot (tools/shots/shot_runner.gd for the game,
## tools/shots/editor_shot_hook.gd for the editor): let the scene settle for some frames,
## wait until the next frame has really been drawn, read the viewport back and save it as a
## PNG. @tool because the editor hook calls it inside the editor.

## Where `make shots` writes its pictures; docs/shots/ holds the chosen copies.
const OUT_DIR := "res://build/shots"
## Frames a screen gets to lay itself out and start its animations before the picture.
const SETTLE_FRAMES := 20


## The PNG a shot named `shot_name` is saved to, e.g. res://build/shots/maze_tilt.png.
static func path_for(shot_name: String) -> String:
	return "%s/%s.png" % [OUT_DIR, shot_name]


## Waits `settle_frames` processed frames and one drawn frame, then saves what `viewport`
## shows to `path` (res:// or absolute; missing folders are made). Returns the save's error
## and prints the outcome either way, so a caller's log says which picture failed and why.
static func save(viewport: Viewport, path: String, settle_frames := SETTLE_FRAMES) -> Error:
	var tree := viewport.get_tree()
	for frame in settle_frames:
		await tree.process_frame
	# The texture holds the last finished frame only after the frame has been drawn.
	await RenderingServer.frame_post_draw
	var image := viewport.get_texture().get_image()
	if image == null or image.is_empty():
		printerr("shots: %s: the viewport gave no image (no display or renderer?)" % path)
		return ERR_UNAVAILABLE
	var absolute := ProjectSettings.globalize_path(path)
	var folder_error := DirAccess.make_dir_recursive_absolute(absolute.get_base_dir())
	if folder_error != OK:
		printerr(
			"shots: cannot make %s: %s" % [absolute.get_base_dir(), error_string(folder_error)]
		)
		return folder_error
	var error := image.save_png(absolute)
	if error != OK:
		printerr("shots: cannot save %s: %s" % [path, error_string(error)])
	else:
		print("shots: wrote %s (%dx%d)" % [path, image.get_width(), image.get_height()])
	return error
