extends SceneTree
## The 3D maze's frame rate, side by side: opens the classic maze as the player does, keeps
## the board tilting round (balls rolling, the board's shadow moving), and measures frames
## per second of this process's CPU time for each variant of the render settings in turn,
## in rounds (A B C A B C ...), so a machine shared with other work treats every variant
## alike. Run by tools/maze_fps.sh under Xvfb (a real window, software GL).
##   MAZE_FPS_ROUNDS=3  MAZE_FPS_FRAMES=40

const ScreenOpener := preload("res://tools/shots/screen_opener.gd")
const AppScript := preload("res://scenes/app/app.gd")
const GAME_SCENE := "res://scenes/maze/maze_game.tscn"
const BOARD := "res://levels/maze/classic.board"
const SCRATCH_SETTINGS := "user://fps_settings.cfg"
const SCRATCH_SAVE := "user://fps_save.cfg"
## Variants: a name and the settings it changes from the game's own ("as shipped" changes
## none). Keys: scale (Viewport.scaling_3d_scale), msaa (Viewport.MSAA_*),
## hide (parts not drawn: floor, walls, frame, balls, table, shadows, panel: the 2D side
## panel, camera: no 3D pass at all), low (the player's
## Low graphics setting), low_scale (Low at another render scale), holes (the board's holes
## drawn as in hard mode, to see them; the game's rules stay as they are).
## MAZE_FPS_ONLY="as shipped|Low graphics" runs only those;
## MAZE_FPS_THREADS=1 prints each thread's CPU ms a frame (llvmpipe's, the engine's).
const VARIANTS := [
	["full res, MSAA 2x (GPU path)", {"scale": 1.0, "msaa": Viewport.MSAA_2X}],
	["as shipped", {}],
	["Low graphics", {"low": true}],
	["Low graphics, half size", {"low": true, "low_scale": 0.5}],
	["full res", {"scale": 1.0}],
	["no shadows", {"hide": ["shadows"]}],
	["no 3D", {"hide": ["floor", "walls", "frame", "balls", "table"]}],
	["Low, no floor", {"low": true, "hide": ["floor"]}],
	["Low, no walls", {"low": true, "hide": ["walls"]}],
	["Low, no board", {"low": true, "hide": ["floor", "walls", "frame", "balls"]}],
	["Low, no panel", {"low": true, "hide": ["panel"]}],
	["Low, no frame", {"low": true, "hide": ["frame"]}],
	["Low, no balls", {"low": true, "hide": ["balls"]}],
	["Low, holes shown", {"low": true, "holes": true}],
	["no camera", {"hide": ["camera"]}],
]

var _angle := 0.0
var _panel: Control


func _initialize() -> void:
	_run.call_deferred()


func _run() -> void:
	for scratch in [SCRATCH_SETTINGS, SCRATCH_SAVE]:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(scratch))
	var app := root.get_node("/root/App") as AppScript
	app.load_player_files(SCRATCH_SETTINGS, SCRATCH_SAVE)
	var game := await ScreenOpener.open(
		self, app.start_game.bind(BoardLevel.MAZE_NAME, BOARD), GAME_SCENE
	)
	if game == null or game.get("rules") == null:
		printerr("maze_fps: the maze did not open")
		quit(1)
		return
	# the game script is not preloaded: it names the App autoload, which a -s script's
	# preloads are compiled before
	var stage: MazeStage = game.call("stage")
	_panel = game.get_node("Side")
	var defaults := _read_settings(stage)
	var rounds := (
		int(OS.get_environment("MAZE_FPS_ROUNDS")) if OS.has_environment("MAZE_FPS_ROUNDS") else 3
	)
	var frames := (
		int(OS.get_environment("MAZE_FPS_FRAMES")) if OS.has_environment("MAZE_FPS_FRAMES") else 40
	)
	var variants := _chosen_variants()
	var rates := {}
	var mains := {}
	for variant: Array in variants:
		rates[variant[0]] = PackedFloat64Array()
		mains[variant[0]] = PackedFloat64Array()
	await _frames(20)  # the game starts on the first tilt; let it settle
	for r in rounds:
		for variant: Array in variants:
			_apply(stage, defaults.merged(variant[1], true))
			await _frames(4)
			var measured := await _measure(frames)
			rates[variant[0]].append(measured[0])
			mains[variant[0]].append(measured[1])
			if r == 0 and OS.has_environment("MAZE_FPS_SHOTS"):
				await _save_shot(variant[0])
	_apply(stage, defaults)
	var size := root.get_visible_rect().size
	print(
		(
			"maze_fps: %dx%d on %s, %d rounds of %d frames"
			% [size.x, size.y, RenderingServer.get_video_adapter_name(), rounds, frames]
		)
	)
	print("maze_fps:   variant                      frames/CPU s (min-max)   main thread ms/frame")
	for variant: Array in variants:
		var list: PackedFloat64Array = rates[variant[0]]
		list.sort()
		var main: PackedFloat64Array = mains[variant[0]]
		main.sort()
		print(
			(
				"maze_fps:   %-28s %5.1f (%.1f-%.1f)      %5.1f"
				% [variant[0], list[list.size() / 2], list[0], list[-1], main[main.size() / 2]]
			)
		)
	_release()
	quit(0)


# The variants named in MAZE_FPS_ONLY (names joined by "|"), or all of them.
func _chosen_variants() -> Array:
	if not OS.has_environment("MAZE_FPS_ONLY"):
		return VARIANTS
	var names := OS.get_environment("MAZE_FPS_ONLY").split("|")
	return VARIANTS.filter(func(variant: Array) -> bool: return names.has(variant[0]))


func _read_settings(_stage: MazeStage) -> Dictionary:
	return {
		"hide": [],
		"low": false,
		"holes": false,
		"scale": root.scaling_3d_scale,
		"msaa": root.msaa_3d,
	}


func _apply(stage: MazeStage, settings: Dictionary) -> void:
	root.scaling_3d_scale = settings["scale"]
	root.msaa_3d = settings["msaa"]
	# Low graphics as the player's setting gives it (its own render size), or at low_scale
	stage.set_look(settings["low"], stage.tutorial_look)
	if settings.has("low_scale"):
		root.scaling_3d_scale = settings["low_scale"]
	var board := stage.board()
	board.set_hard_mode(settings["holes"])
	var parts := {
		"floor": [board.part("floor")],
		"walls": [board.part("walls")],
		"frame": [board.part("frame")],
		"balls": [stage.balls()],
		"table": [stage.table()],
	}
	if settings["low"]:
		parts.erase("table")  # hidden by the setting
		parts["floor"].append(board.part("marks"))  # Low's goal and holes lie on the floor
	for part: String in parts:
		for node: Node3D in parts[part]:
			node.visible = not settings["hide"].has(part)
	# the side panel (2D), and the camera (none: no 3D pass at all)
	_panel.visible = not settings["hide"].has("panel")
	stage.camera().current = not settings["hide"].has("camera")
	if settings["low"]:
		return
	# the shadows are the floor shader's
	board.floor_material().set_shader_parameter("shadows_on", not settings["hide"].has("shadows"))


# Saves the window as build/maze_fps/<variant>.png, to see what a variant looks like.
func _save_shot(variant_name: String) -> void:
	await RenderingServer.frame_post_draw
	var folder := ProjectSettings.globalize_path("res://build/maze_fps")
	DirAccess.make_dir_recursive_absolute(folder)
	var file_name := variant_name.replace(" ", "_").replace(",", "")
	root.get_texture().get_image().save_png("%s/%s.png" % [folder, file_name])


# [frames per CPU second, CPU ms a frame on the main thread] over `count` frames.
func _measure(count: int) -> Array[float]:
	var main_stat := "/proc/self/task/%d/stat" % OS.get_process_id()
	var cpu_start := _cpu_seconds()
	var main_start := _cpu_seconds(main_stat)
	var threads_start := _thread_seconds()
	await _frames(count)
	if OS.has_environment("MAZE_FPS_THREADS"):
		var threads_end := _thread_seconds()
		var parts := PackedStringArray()
		for name: String in threads_end:
			var spent: float = threads_end[name] - threads_start.get(name, 0.0)
			parts.append("%s %.1f" % [name, spent * 1000.0 / count])
		print("maze_fps: threads ms/frame: ", ", ".join(parts))
	var cpu := maxf(_cpu_seconds() - cpu_start, 0.001)
	var main := _cpu_seconds(main_stat) - main_start
	return [count / cpu, main * 1000.0 / count]


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


# CPU seconds of this process's threads, summed by thread name.
static func _thread_seconds() -> Dictionary:
	var totals := {}
	for task in DirAccess.get_directories_at("/proc/self/task"):
		var file := FileAccess.open("/proc/self/task/%s/stat" % task, FileAccess.READ)
		if file == null:
			continue
		var text := file.get_line()
		var name := text.substr(text.find("(") + 1, text.rfind(")") - text.find("(") - 1)
		var fields := text.substr(text.rfind(")") + 2).split(" ")
		totals[name] = (
			totals.get(name, 0.0) + (fields[11].to_float() + fields[12].to_float()) / 100.0
		)
	return totals


# User + system CPU seconds of this process, all its threads (software GL's too).
static func _cpu_seconds(path := "/proc/self/stat") -> float:
	var file := FileAccess.open(path, FileAccess.READ)
	if file == null:
		return 0.0
	var text := file.get_line()
	var fields := text.substr(text.rfind(")") + 2).split(" ")
	return (fields[11].to_float() + fields[12].to_float()) / 100.0
