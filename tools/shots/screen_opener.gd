extends RefCounted
## Opens a game screen the way the player reaches it (a call on the App autoload that changes
## the scene, such as App.start_game) and waits until the new scene is the current one.

const AppScript := preload("res://scenes/app/app.gd")
## Scene changes are deferred to the end of a frame; a few frames are plenty.
const MAX_FRAMES := 60


## Calls `change` and returns the new current scene once its file is `scene_path`, or null
## (with an error printed) when that does not happen within MAX_FRAMES frames.
static func open(tree: SceneTree, change: Callable, scene_path: String) -> Node:
	var before := tree.current_scene
	change.call()
	for frame in MAX_FRAMES:
		await tree.process_frame
		var scene := tree.current_scene
		# The same screen opened twice in a row is a new instance, not the old one.
		if scene != null and scene != before and scene.scene_file_path == scene_path:
			await tree.process_frame
			# a screen that draws itself over a few frames (the maze) keeps the curtain up
			var curtain := (tree.root.get_node("/root/App") as AppScript).curtain
			for wait in MAX_FRAMES:
				if not curtain.is_covering():
					break
				await tree.process_frame
			return scene
	printerr("shots: %s did not open within %d frames" % [scene_path, MAX_FRAMES])
	return null
