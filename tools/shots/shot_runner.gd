extends SceneTree
## Renders the main screens to build/shots/*.png (make shots). Needs a real window: run it
## under Xvfb with the GL Compatibility renderer (tools/shots.sh does).
##
## Each shot opens a scene; when the scene's root has `prepare_shot(name)`, the runner calls
## it (and awaits it) so the scene can put itself in the state worth showing (mid-tilt,
## many balls in play, ...), then waits a few frames and saves the viewport.

const OUT_DIR := "res://build/shots"
const SHOTS: Array[Dictionary] = [
	{"name": "menu_main", "scene": "res://scenes/menu/main_menu.tscn"},
	{"name": "menu_level_select_pachinko", "scene": "res://scenes/menu/level_select.tscn"},
	{"name": "menu_level_select_maze", "scene": "res://scenes/menu/level_select.tscn"},
	{"name": "menu_settings", "scene": "res://scenes/menu/settings_menu.tscn"},
	{"name": "pachinko_start", "scene": "res://scenes/pachinko/pachinko_game.tscn"},
	{"name": "pachinko_play", "scene": "res://scenes/pachinko/pachinko_game.tscn"},
	{"name": "pachinko_win", "scene": "res://scenes/pachinko/pachinko_game.tscn"},
	{"name": "pachinko_over", "scene": "res://scenes/pachinko/pachinko_game.tscn"},
]
# Pictures must never touch the player's own settings and best results.
const SCRATCH_SETTINGS := "user://shots_settings.cfg"
const SCRATCH_SAVE := "user://shots_save.cfg"
const SETTLE_FRAMES := 20


func _initialize() -> void:
	_run.call_deferred()


func _run() -> void:
	DirAccess.make_dir_recursive_absolute(ProjectSettings.globalize_path(OUT_DIR))
	DirAccess.remove_absolute(ProjectSettings.globalize_path(SCRATCH_SAVE))
	var app := root.get_node("/root/App")
	app.call("load_player_files", SCRATCH_SETTINGS, SCRATCH_SAVE)
	var only := OS.get_environment("SHOTS_ONLY")
	var failures := 0
	for shot in SHOTS:
		var shot_name: String = shot["name"]
		if not only.is_empty() and not shot_name.begins_with(only):
			continue
		if not await _take(shot_name, shot["scene"]):
			failures += 1
	quit(1 if failures > 0 else 0)


func _take(shot_name: String, scene_path: String) -> bool:
	if not ResourceLoader.exists(scene_path):
		printerr("shots: %s: scene %s does not exist" % [shot_name, scene_path])
		return false
	var packed: PackedScene = load(scene_path)
	var scene := packed.instantiate()
	if current_scene != null:
		current_scene.queue_free()
	root.add_child(scene)
	current_scene = scene
	await process_frame
	if scene.has_method("prepare_shot"):
		await scene.call("prepare_shot", shot_name)
	for i in SETTLE_FRAMES:
		await process_frame
	await RenderingServer.frame_post_draw
	var image := root.get_texture().get_image()
	var path := "%s/%s.png" % [OUT_DIR, shot_name]
	var error := image.save_png(ProjectSettings.globalize_path(path))
	if error != OK:
		printerr("shots: could not save %s (error %d)" % [path, error])
		return false
	print("shots: %s" % path)
	return true
