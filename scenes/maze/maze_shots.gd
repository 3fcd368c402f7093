extends Node
## Screenshot driver (`make shots` / Xvfb): plays the maze scene through four moments and
## saves build/shots/maze_start.png, maze_tilt.png, maze_win.png, maze_lost.png.
## Moments are staged through the rules (balls placed, tilt set), never by faking the view.

const GAME := preload("res://scenes/maze/maze_game.tscn")
const OUT := "res://build/shots/"


func _ready() -> void:
	for arg in OS.get_cmdline_user_args():
		if arg.begins_with("--size="):
			var parts := arg.trim_prefix("--size=").split("x")
			get_window().size = Vector2i(int(parts[0]), int(parts[1]))
			await get_tree().process_frame
	DirAccess.make_dir_recursive_absolute(ProjectSettings.globalize_path(OUT))
	var game: Control = GAME.instantiate()
	add_child(game)
	await _settle(0.6)
	await _save("maze_start")
	var rules: MazeRules = game.get("rules")
	# Mid-tilt: start, tilt down-right through the joystick, let the balls roll.
	game.call("_start")
	var mixer: RefCounted = game.get("mixer")
	var joystick: Control = game.get("_joystick")
	joystick.set("head_offset", Vector2(11.0, 8.0))
	mixer.call("joystick_moved", Vector2(11.0, 8.0))
	await _settle(1.3)
	await _save("maze_tilt")
	# Win: let the autoplay's pilot play the live scene (the first seed that wins).
	var pilot_script: GDScript = load("res://scripts/maze/maze_pilot.gd")
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
	joystick.set("head_offset", Vector2.ZERO)
	game.call("_start")
	mixer.call("joystick_moved", Vector2(8.0, -2.0))
	joystick.set("head_offset", Vector2(8.0, -2.0))
	var waited := 0.0
	while rules.is_playing() and waited < 5.0:
		await get_tree().process_frame
		waited += get_process_delta_time()
	await _settle(2.2)
	await _save("maze_lost")
	get_tree().quit()


func _settle(seconds: float) -> void:
	await get_tree().create_timer(seconds).timeout


func _save(shot: String) -> void:
	await RenderingServer.frame_post_draw
	await RenderingServer.frame_post_draw
	var image := get_viewport().get_texture().get_image()
	var suffix := "" if image.get_width() == 1280 else "_%d" % image.get_width()
	image.save_png(OUT + shot + suffix + ".png")
	print("saved ", OUT + shot + suffix + ".png")
