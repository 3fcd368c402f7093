extends SceneTree
## Measures how launch power aims on a pachinko board: fires lone balls (one at a time, so
## nothing but power decides their path) at powers from the weakest clearing shot to 100,
## and reports where each first touched a pin (its entry x), where it ended (a pocket, the
## gutter) and the total-variation distance between the outcomes of the weakest and the
## strongest fifth of power.
##   tools/godot.sh --headless --path . -s tools/power_sweep.gd -- --board=classic [--step=0.5]
##   [--rail-end=-55] [--json] [--paths=out.png]


func _init() -> void:
	var args := {"board": "classic", "step": "0.5", "rail-end": "", "json": ""}
	for arg in OS.get_cmdline_user_args():
		var parts := arg.trim_prefix("--").split("=", true, 1)
		args[parts[0]] = parts[1] if parts.size() > 1 else "yes"
	var path := "res://levels/pachinko/%s.board" % args["board"]
	var loaded := BoardLoader.load_board(path)
	if loaded.level == null:
		printerr("power_sweep: %s" % loaded.error)
		quit(1)
		return
	var level := loaded.level
	if args["rail-end"] != "":
		level.rail_end_deg = float(args["rail-end"])
	if args.has("paths"):
		_draw_paths(level, args["paths"])
		quit()
		return
	var report := PowerAim.sweep(level, float(args["step"]))
	if args["json"] != "":
		print(JSON.stringify(report))
	else:
		print(PowerAim.describe(report))
	quit()


# Draws the board's pins and the first seconds of lone shots at a few powers.
func _draw_paths(level: BoardLevel, path: String) -> void:
	var image := Image.create(int(level.size.x), int(level.size.y), false, Image.FORMAT_RGB8)
	image.fill(Color(0.08, 0.08, 0.12))
	for p in level.pins:
		_dot(image, p, Color(0.6, 0.6, 0.6), 1)
	for i in 720:
		var a := TAU * i / 720.0
		_dot(image, level.ring_center + Vector2(cos(a), sin(a)) * level.ring_radius, Color.WHITE, 0)
	var colors := [Color.RED, Color.ORANGE, Color.YELLOW, Color.GREEN, Color.CYAN, Color.MAGENTA]
	var powers := [14.0, 30.0, 45.0, 60.0, 80.0, 100.0]
	for k in powers.size():
		var board := level.duplicate() as BoardLevel
		var rules := PachinkoRules.new(board, 1)
		rules.start_game()
		var id := rules.fire(powers[k])
		for i in int(2.5 / rules.step_seconds()):
			rules.step()
			if not rules.world.has_ball(id):
				break
			_dot(image, rules.world.get_ball_position(id), colors[k], 0)
	image.save_png(path)


func _dot(image: Image, at: Vector2, color: Color, r: int) -> void:
	for dx in range(-r, r + 1):
		for dy in range(-r, r + 1):
			var x := int(at.x) + dx
			var y := int(at.y) + dy
			if x >= 0 and y >= 0 and x < image.get_width() and y < image.get_height():
				image.set_pixel(x, y, color)
