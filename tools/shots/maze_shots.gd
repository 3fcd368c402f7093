extends Node
## Screenshot driver (`make shots` / Xvfb): plays the maze scene through four moments and
## saves build/shots/maze_start.png, maze_tilt.png, maze_win.png, maze_lost.png.
## Moments are staged through the rules (balls placed, tilt set), never by faking the view.

const GAME := preload("res://scenes/maze/maze_game.tscn")
const OUT := "res://build/shots/"
const SHOT_SETTINGS := "user://shots_settings.cfg"
const SHOT_SAVE := "user://shots_save.cfg"


func _ready() -> void:
	for arg in OS.get_cmdline_user_args():
		if arg.begins_with("--size="):
			var parts := arg.trim_prefix("--size=").split("x")
			get_window().size = Vector2i(int(parts[0]), int(parts[1]))
			await get_tree().process_frame
	DirAccess.make_dir_recursive_absolute(ProjectSettings.globalize_path(OUT))
	# Scratch player files: pictures must not touch the real best times.
	DirAccess.remove_absolute(ProjectSettings.globalize_path(SHOT_SAVE))
	App.load_player_files(SHOT_SETTINGS, SHOT_SAVE)
	var game: Control = GAME.instantiate()
	add_child(game)
	await _settle(0.6)
	await _save("maze_start")
	var rules: MazeRules = game.get("rules")
	# Mid-tilt: press the joystick head and drag it down-right with real mouse events.
	var joystick: Control = game.get("_joystick")
	# Events arrive in window pixels; the stretched canvas maps them back to UI units.
	var head := get_viewport().get_final_transform() * joystick.get_global_rect().get_center()
	_mouse_button(head, true)
	await get_tree().process_frame
	_mouse_button(head, false)
	for i in 12:
		_mouse_motion(head + Vector2(22.0, 16.0) * float(i + 1) / 12.0)
		await get_tree().process_frame
	await _settle(1.3)
	await _save("maze_tilt")
	# Win: let the autoplay's pilot play the live scene (the first seed that wins).
	var pilot_script: GDScript = load("res://scripts/maze/autoplay/maze_pilot.gd")
	for attempt in range(1, 11):
		rules.reset()
		game.call("_start")
		var rng := RandomNumberGenerator.new()
		rng.seed = attempt
		var pilot: RefCounted = pilot_script.new(rules.level, false, rng, rules.step_seconds())
		var guard := 0
		while rules.is_playing() and guard < 14400:
			var w := rules.world
			rules.set_tilt(pilot.call("decide", w.get_positions(), w.get_velocities()))
			rules.step()
			guard += 1
		if rules.state == MazeRules.State.WON:
			break
	await _settle(2.2)
	await _save("maze_win")
	# Hard-mode loss: tilt right; the top-left ball rolls along the top row into a hole.
	rules.set_hard_mode(true)
	_mouse_button(head, true)
	await get_tree().process_frame
	_mouse_motion(head + Vector2(16.0, -4.0))
	var waited := 0.0
	while rules.is_playing() and waited < 5.0:
		await get_tree().process_frame
		waited += get_process_delta_time()
	await _settle(2.2)
	await _save("maze_lost")
	get_tree().quit()


func _mouse_button(at: Vector2, down: bool) -> void:
	var event := InputEventMouseButton.new()
	event.button_index = MOUSE_BUTTON_LEFT
	event.pressed = down
	event.position = at
	event.global_position = at
	Input.parse_input_event(event)


func _mouse_motion(at: Vector2) -> void:
	var event := InputEventMouseMotion.new()
	event.position = at
	event.global_position = at
	Input.parse_input_event(event)


func _settle(seconds: float) -> void:
	await get_tree().create_timer(seconds).timeout


func _save(shot: String) -> void:
	await RenderingServer.frame_post_draw
	await RenderingServer.frame_post_draw
	var image := get_viewport().get_texture().get_image()
	var suffix := "" if image.get_width() == 1280 else "_%d" % image.get_width()
	image.save_png(OUT + shot + suffix + ".png")
	print("saved ", OUT + shot + suffix + ".png")
