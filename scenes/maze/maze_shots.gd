extends Node
## Screenshot driver (`make shots` / Xvfb): plays the maze scene through four moments and
## saves build/shots/maze_start.png, maze_tilt.png, maze_win.png, maze_lost.png.
## Moments are staged through the rules (balls placed, tilt set), never by faking the view.

const GAME := preload("res://scenes/maze/maze_game.tscn")
const OUT := "res://build/shots/"


func _ready() -> void:
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
	# Win: run the autoplay's pilot in the live scene until every ball is in.
	rules.reset()
	game.call("_start")
	var pilot_script: GDScript = load("res://scripts/maze/maze_pilot.gd")
	var rng := RandomNumberGenerator.new()
	rng.seed = 1
	var pilot: RefCounted = pilot_script.new(rules.level, false, rng, rules.step_seconds())
	var guard := 0
	while rules.is_playing() and guard < 40000:
		var w := rules.world
		rules.set_tilt(pilot.call("decide", w.get_positions(), w.get_velocities()))
		rules.step()
		guard += 1
	await _settle(2.2)
	await _save("maze_win")
	# Hard-mode loss: roll a ball straight into a hole.
	rules.set_hard_mode(true)
	game.call("_start")
	var id := rules.world.get_ids()[0]
	rules.world.set_ball_position(id, rules.level.holes[1] + Vector2(-14.0, 0.0))
	rules.world.set_ball_velocity(id, Vector2(90.0, 0.0))
	rules.set_tilt(Vector2(6.0, 0.0))
	for i in 60:
		rules.step()
	await _settle(2.2)
	await _save("maze_lost")
	get_tree().quit()


func _settle(seconds: float) -> void:
	await get_tree().create_timer(seconds).timeout


func _save(shot: String) -> void:
	await RenderingServer.frame_post_draw
	await RenderingServer.frame_post_draw
	var image := get_viewport().get_texture().get_image()
	image.save_png(OUT + shot + ".png")
	print("saved ", OUT + shot + ".png")
