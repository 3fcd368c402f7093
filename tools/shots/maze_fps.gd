extends SceneTree
## The 3D maze's frame rate, side by side: opens the classic maze as the player does, keeps
## the board tilting round (balls rolling, the board's shadow moving), and measures frames
## per second of this process's CPU time for each variant of the render settings in turn,
## in rounds (A B C A B C ...), so a machine shared with other work treats every variant
## alike. Run by tools/maze_fps.sh under Xvfb (a real window, software GL).
##   MAZE_FPS_ROUNDS=3  MAZE_FPS_FRAMES=40

const ScreenOpener := preload("res://tools/shots/screen_opener.gd")
## The stage's own shadow map size (the game scripts themselves are loaded once App exists).
const SHADOW_MAP_SIZE: int = preload("res://scenes/maze/maze_stage.gd").SHADOW_MAP_SIZE
const GAME_SCENE := "res://scenes/maze/maze_game.tscn"
const BOARD := "res://levels/maze/classic.board"
const SCRATCH_SETTINGS := "user://fps_settings.cfg"
const SCRATCH_SAVE := "user://fps_save.cfg"
## Variants: a name and the settings it changes from the game's own ("as shipped" changes
## none). Keys: scale (Viewport.scaling_3d_scale), msaa (Viewport.MSAA_*), shadow_map
## (texels, 0 = no sun shadows).
const MSAA_OFF := Viewport.MSAA_DISABLED
const MSAA_2X := Viewport.MSAA_2X
const VARIANTS := [
	["before (full res, MSAA 2x)", {"scale": 1.0, "msaa": MSAA_2X, "fxaa": false}],
	["as shipped", {}],
	["scale 0.6", {"scale": 0.6}],
	["scale 0.75", {"scale": 0.75}],
	["full res, FXAA", {"scale": 1.0}],
	["as shipped, map 1024", {"shadow_map": 1024}],
	["as shipped, no sun shadow", {"shadow_map": 0}],
]

var _angle := 0.0


func _initialize() -> void:
	_run.call_deferred()


func _run() -> void:
	for scratch in [SCRATCH_SETTINGS, SCRATCH_SAVE]:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(scratch))
	var app := root.get_node("/root/App")
	app.call("load_player_files", SCRATCH_SETTINGS, SCRATCH_SAVE)
	var game := await ScreenOpener.open(
		self, app.call.bind("start_game", "maze", BOARD), GAME_SCENE
	)
	if game == null or game.get("rules") == null:
		printerr("maze_fps: the maze did not open")
		quit(1)
		return
	var stage: Node3D = game.call("stage")
	var defaults := _read_settings(stage)
	var rounds := (
		int(OS.get_environment("MAZE_FPS_ROUNDS")) if OS.has_environment("MAZE_FPS_ROUNDS") else 3
	)
	var frames := (
		int(OS.get_environment("MAZE_FPS_FRAMES")) if OS.has_environment("MAZE_FPS_FRAMES") else 40
	)
	var rates := {}
	for variant: Array in VARIANTS:
		rates[variant[0]] = PackedFloat64Array()
	await _frames(20)  # the game starts on the first tilt; let it settle
	for r in rounds:
		for variant: Array in VARIANTS:
			_apply(stage, defaults.merged(variant[1], true))
			await _frames(4)
			rates[variant[0]].append(await _measure(frames))
			if r == 0 and OS.has_environment("MAZE_FPS_SHOTS"):
				await _save_shot(variant[0])
	_apply(stage, defaults)
	var size := root.get_visible_rect().size
	print(
		(
			"maze_fps: %dx%d on %s, %d rounds of %d frames, frames per CPU second (median, min-max):"
			% [size.x, size.y, RenderingServer.get_video_adapter_name(), rounds, frames]
		)
	)
	for variant: Array in VARIANTS:
		var list: PackedFloat64Array = rates[variant[0]]
		list.sort()
		print(
			(
				"maze_fps:   %-24s %5.1f  (%.1f-%.1f)"
				% [variant[0], list[list.size() / 2], list[0], list[list.size() - 1]]
			)
		)
	_release()
	quit(0)


func _read_settings(stage: Node3D) -> Dictionary:
	var sun: DirectionalLight3D = stage.call("sun")
	return {
		"hide": [],
		"fxaa": root.screen_space_aa == Viewport.SCREEN_SPACE_AA_FXAA,
		"shadow_quality":
		ProjectSettings.get_setting(
			"rendering/lights_and_shadows/directional_shadow/soft_shadow_filter_quality"
		),
		"sky": true,
		"side": true,
		"stage": true,
		"scale": root.scaling_3d_scale,
		"msaa": root.msaa_3d,
		"shadow_map": SHADOW_MAP_SIZE if sun.shadow_enabled else 0,
	}


func _apply(stage: Node3D, settings: Dictionary) -> void:
	root.scaling_3d_scale = settings["scale"]
	root.msaa_3d = settings["msaa"]
	root.screen_space_aa = (
		Viewport.SCREEN_SPACE_AA_FXAA if settings["fxaa"] else Viewport.SCREEN_SPACE_AA_DISABLED
	)
	RenderingServer.directional_soft_shadow_filter_set_quality(settings["shadow_quality"])
	var sun: DirectionalLight3D = stage.call("sun")
	stage.get_parent().get_node("Side").visible = settings["side"]
	stage.visible = settings["stage"]
	var parts := {
		"floor": stage.call("board").call("part", "floor"),
		"walls": stage.call("board").call("part", "walls"),
		"frame": stage.call("board").call("part", "frame"),
		"balls": stage.call("balls"),
		"table": stage.get("_table"),
		"key": stage.get("_key"),
	}
	for part: String in parts:
		(parts[part] as Node3D).visible = not settings["hide"].has(part)
	for child in stage.get_children():
		var env := child as WorldEnvironment
		if env != null:
			env.environment.reflected_light_source = (
				Environment.REFLECTION_SOURCE_SKY
				if settings["sky"]
				else Environment.REFLECTION_SOURCE_BG
			)
			env.environment.background_mode = Environment.BG_COLOR
	var shadow_map: int = settings["shadow_map"]
	sun.shadow_enabled = shadow_map > 0
	if shadow_map > 0:
		RenderingServer.directional_shadow_atlas_set_size(shadow_map, true)


# Saves the window as build/maze_fps/<variant>.png, to see what a variant looks like.
func _save_shot(variant_name: String) -> void:
	await RenderingServer.frame_post_draw
	var folder := ProjectSettings.globalize_path("res://build/maze_fps")
	DirAccess.make_dir_recursive_absolute(folder)
	var file_name := variant_name.replace(" ", "_").replace(",", "")
	root.get_texture().get_image().save_png("%s/%s.png" % [folder, file_name])


# Frames per CPU second over `count` frames; prints the main thread's share.
func _measure(count: int) -> float:
	var cpu_start := _cpu_seconds()
	var main_start := _cpu_seconds("/proc/self/task/%d/stat" % OS.get_process_id())
	await _frames(count)
	var cpu := maxf(_cpu_seconds() - cpu_start, 0.001)
	var main := _cpu_seconds("/proc/self/task/%d/stat" % OS.get_process_id()) - main_start
	print(
		(
			"maze_fps: (%.0f ms CPU a frame, %.0f ms of it on the main thread)"
			% [cpu * 1000.0 / count, main * 1000.0 / count]
		)
	)
	return count / cpu


# Runs `count` frames, tilting round as a player steering would.
func _frames(count: int) -> void:
	for i in count:
		_angle += 0.05
		_tilt(Vector2(cos(_angle), sin(_angle * 1.3)))
		await process_frame


func _tilt(strength: Vector2) -> void:
	_release()
	Input.action_press("tilt_right" if strength.x > 0.0 else "tilt_left", absf(strength.x))
	Input.action_press("tilt_down" if strength.y > 0.0 else "tilt_up", absf(strength.y))


func _release() -> void:
	for action: StringName in [&"tilt_left", &"tilt_right", &"tilt_up", &"tilt_down"]:
		Input.action_release(action)


# User + system CPU seconds of this process, all its threads (software GL's too).
static func _cpu_seconds(path := "/proc/self/stat") -> float:
	var file := FileAccess.open(path, FileAccess.READ)
	if file == null:
		return 0.0
	var text := file.get_line()
	var fields := text.substr(text.rfind(")") + 2).split(" ")
	return (fields[11].to_float() + fields[12].to_float()) / 100.0
