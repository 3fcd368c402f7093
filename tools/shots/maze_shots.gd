extends RefCounted
## The maze shots: "maze_start" the waiting board, "maze_tilt" the board mid-tilt under the
## arrow keys, "maze_win" a board the autoplay's pilot solved, "maze_lost" hard mode with a
## ball in a black hole. Each opens the game as the level select does (App.start_game) and
## plays it with the player's own input actions or through the screen's rules
## (MazeGame.rules); balls are never placed by hand.

const ShotCapture := preload("res://tools/shots/shot_capture.gd")
const ScreenOpener := preload("res://tools/shots/screen_opener.gd")
const MazeGame := preload("res://scenes/maze/maze_game.gd")
const MazePilot := preload("res://scripts/maze/autoplay/maze_pilot.gd")
const GAME_SCENE := "res://scenes/maze/maze_game.tscn"
const BOARD := "res://levels/maze/classic.board"
## The shots this file takes, in order.
const NAMES: Array[String] = ["maze_start", "maze_tilt", "maze_win", "maze_lost"]
## Pilot seeds tried, and physics steps per try, before the win shot gives up.
const WIN_ATTEMPTS := 10
const WIN_MAX_STEPS := 14400
## How long a tilt that should drop a ball into a hole may take.
const LOSS_TIMEOUT := 5.0


## Opens the game, plays it into the moment of `shot_name` and saves it. OK or the reason
## it failed.
static func take(tree: SceneTree, shot_name: String) -> Error:
	if not shot_name in NAMES:
		printerr("shots: maze_shots has no shot '%s'" % shot_name)
		return ERR_INVALID_PARAMETER
	var game := await ScreenOpener.open(tree, App.start_game.bind("maze", BOARD), GAME_SCENE)
	if game == null:
		return ERR_CANT_OPEN
	var rules := (game as MazeGame).rules
	if rules == null:
		printerr("shots: %s: the game has no rules (the board did not load)" % shot_name)
		return ERR_CANT_OPEN
	var staged := OK
	match shot_name:
		"maze_start":
			await _wait(tree, 0.6)  # the note fades in
		"maze_tilt":
			# Right and a little down, as a gamepad stick pushed part way.
			_press_tilt(Vector2(0.9, 0.6))
			await _wait(tree, 1.3)
		"maze_win":
			staged = await _win(tree, rules)
			await _wait(tree, 2.2)  # the board levels out and the note comes up
		"maze_lost":
			staged = await _lose(tree, rules)
	if staged != OK:
		return staged
	var error: Error = await ShotCapture.save(tree.root, ShotCapture.path_for(shot_name))
	_release_tilt()
	return error


# Holds the tilt_* actions at `strength` (x right, y down), as arrow keys or a stick do;
# the first tilt starts the game. They stay held until _release_tilt.
static func _press_tilt(strength: Vector2) -> void:
	if strength.x != 0.0:
		Input.action_press("tilt_right" if strength.x > 0.0 else "tilt_left", absf(strength.x))
	if strength.y != 0.0:
		Input.action_press("tilt_down" if strength.y > 0.0 else "tilt_up", absf(strength.y))


static func _release_tilt() -> void:
	for action: StringName in [&"tilt_left", &"tilt_right", &"tilt_up", &"tilt_down"]:
		Input.action_release(action)


# Lets the autoplay's pilot play the live rules, one seed after another, until one wins.
static func _win(tree: SceneTree, rules: MazeRules) -> Error:
	for attempt in range(1, WIN_ATTEMPTS + 1):
		rules.reset()
		_press(&"game_start")
		await tree.process_frame  # the game takes its input on the next frame
		if not rules.is_playing():
			printerr("shots: maze_win: the start key did not start the game")
			return FAILED
		var rng := RandomNumberGenerator.new()
		rng.seed = attempt
		var pilot := MazePilot.new(rules.level, false, rng, rules.step_seconds())
		var steps := 0
		while rules.is_playing() and steps < WIN_MAX_STEPS:
			rules.set_tilt(pilot.decide(rules.world.get_positions(), rules.world.get_velocities()))
			rules.step()
			steps += 1
		if rules.state == MazeRules.State.WON:
			return OK
	printerr("shots: maze_win: the pilot won none of %d tries" % WIN_ATTEMPTS)
	return FAILED


# Hard mode, then tilt right: on the classic board the top-left ball rolls along the top
# row into a hole.
static func _lose(tree: SceneTree, rules: MazeRules) -> Error:
	rules.set_hard_mode(true)
	await tree.process_frame
	_press_tilt(Vector2(1.0, -0.25))
	var waited := 0.0
	while not rules.is_over():
		if waited >= LOSS_TIMEOUT:
			_release_tilt()
			printerr("shots: maze_lost: no ball fell into a hole in %.0f s" % LOSS_TIMEOUT)
			return FAILED
		await tree.process_frame
		waited += tree.root.get_process_delta_time()
	_release_tilt()
	await _wait(tree, 2.2)  # the board levels out and the note comes up
	return OK if rules.state == MazeRules.State.LOST else FAILED


# The player's key press for `action`, through the same input path a keyboard takes.
static func _press(action: StringName) -> void:
	var event := InputEventAction.new()
	event.action = action
	event.pressed = true
	Input.parse_input_event(event)
	var release := InputEventAction.new()
	release.action = action
	Input.parse_input_event(release)


static func _wait(tree: SceneTree, seconds: float) -> void:
	await tree.create_timer(seconds).timeout
