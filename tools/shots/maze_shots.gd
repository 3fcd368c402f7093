extends RefCounted
## The maze shots: "maze_start" the waiting board, "maze_tilt" the board mid-tilt under the
## arrow keys, "maze_win" a board the autoplay's pilot solved, "maze_lost" hard mode with a
## ball in a black hole, "maze_fall" a ball half way down a hole, "maze_ghost" a second
## attempt beside the ghost of the best run (the autoplay's winning run, saved as the game
## saves a best run). Replays go to a scratch folder, never the player's. Each opens the game as the
## level select does (App.start_game) and plays it with the player's own input actions or
## through the screen's rules (MazeGame.rules); balls are never placed by hand. The start and
## tilt shots also print the frame rate.

const ShotCapture := preload("res://tools/shots/shot_capture.gd")
const ScreenOpener := preload("res://tools/shots/screen_opener.gd")
const GAME_SCENE := "res://scenes/maze/maze_game.tscn"
const BOARD := "res://levels/maze/classic.board"
## The shots this file takes, in order.
const NAMES: Array[String] = [
	"maze_start", "maze_tilt", "maze_fine", "maze_win", "maze_lost", "maze_fall", "maze_ghost"
]
## Where the shots' replays (best runs) go instead of the player's folder.
const SCRATCH_REPLAYS := "user://shots_replays"
## The best run the ghost shot plays: the autoplay's pilot with this seed, for at most this
## long (it wins the classic board in about 50 s).
const GHOST_SEED := 2
const GHOST_RUN_SECONDS := 120.0
## The second attempt: tilted this way (up and left, while the best run rolls down first)
## for this long before the shot.
const GHOST_LIVE_TILT := Vector2(-0.7, -0.9)
const GHOST_SHOT_SECONDS := 1.6
## Pilot seeds tried, and physics steps per try, before the win shot gives up.
const WIN_ATTEMPTS := 10
const WIN_MAX_STEPS := 14400
## How long a tilt that should drop a ball into a hole may take.
const LOSS_TIMEOUT := 5.0
## How far down its hole the ball is in the fall shot (0 at the rim, 1 out of sight).
const FALL_SHOT_PROGRESS := 0.4
## How long the frame rate is measured in the tilt shot, in seconds.
const FPS_SECONDS := 3.0


## Opens the game, plays it into the moment of `shot_name` and saves it. OK or the reason
## it failed.
static func take(tree: SceneTree, shot_name: String) -> Error:
	var player_folder := ReplayStore.folder
	ReplayStore.folder = SCRATCH_REPLAYS
	var error: Error = await _take(tree, shot_name)
	ReplayStore.folder = player_folder
	return error


static func _take(tree: SceneTree, shot_name: String) -> Error:
	if not shot_name in NAMES:
		printerr("shots: maze_shots has no shot '%s'" % shot_name)
		return ERR_INVALID_PARAMETER
	var game := await ScreenOpener.open(
		tree, App.start_game.bind(BoardLevel.MAZE_NAME, BOARD), GAME_SCENE
	)
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
			await _report_fps(tree, shot_name)  # drawing only: nothing moves yet
		"maze_tilt":
			# Right and a little down, as a gamepad stick pushed part way.
			_press_tilt(Vector2(0.9, 0.6))
			await _wait(tree, 1.3)
			await _report_fps(tree, shot_name)
		"maze_fine":
			# Right held with the fine key: FINE by the joystick, its head at half reach
			Input.action_press("tilt_fine")
			_press_tilt(Vector2(1.0, 0.0))
			await _wait(tree, 1.0)
		"maze_win":
			staged = await _win(tree, rules)
			await _wait(tree, 2.2)  # the board levels out and the note comes up
		"maze_lost":
			staged = await _lose(tree, rules)
			if staged == OK:
				await _wait(tree, 2.2)  # the board levels out and the note comes up
		"maze_fall":
			staged = await _lose(tree, rules)
			if staged == OK:
				staged = await _mid_fall(tree, (game as MazeGame).stage())
			if staged == OK:  # the fall is under way: take the very next frame
				return await ShotCapture.save(tree.root, ShotCapture.path_for(shot_name), 0)
		"maze_ghost":
			staged = await _second_attempt(tree, game as MazeGame)
	if staged != OK:
		return staged
	var error: Error = await ShotCapture.save(tree.root, ShotCapture.path_for(shot_name))
	_release_tilt()
	Input.action_release("tilt_fine")
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


# Saves the pilot's winning run as the best run (as the game saves one), then starts a new
# attempt tilted another way: the screen shows the best run's ghost beside the live balls.
static func _second_attempt(tree: SceneTree, game: MazeGame) -> Error:
	var rules := game.rules
	var recorder := ReplayRecorder.new()
	var run := MazeAutoplay.run(rules.level, GHOST_RUN_SECONDS, GHOST_SEED, false, recorder)
	if not run.get("won", false):
		printerr("shots: maze_ghost: the pilot did not win: %s" % run)
		return FAILED
	var best := recorder.finish()
	var path := ReplayStore.best_maze_path(rules.level.board_id, false)
	if ReplayStore.save(best, path) != OK:
		printerr("shots: maze_ghost: could not save %s" % path)
		return FAILED
	App.record_maze_time(rules.level.board_id, false, best.seconds)
	rules.reset()  # a new attempt: the screen loads the best run as its ghost
	await tree.process_frame
	_press_tilt(GHOST_LIVE_TILT)  # the first tilt starts the attempt
	await _wait(tree, GHOST_SHOT_SECONDS)
	if (game as MazeGame).ghost() == null:
		_release_tilt()
		printerr("shots: maze_ghost: the second attempt shows no ghost")
		return FAILED
	return OK


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
	return OK if rules.state == MazeRules.State.LOST else FAILED


# Waits until the lost ball is about half way down its hole.
static func _mid_fall(tree: SceneTree, stage: MazeStage) -> Error:
	for frame in 120:
		if stage.balls().fall_progress() >= FALL_SHOT_PROGRESS:
			return OK
		await tree.process_frame
	printerr("shots: maze_fall: no ball fell into a hole")
	return FAILED


# The player's key press for `action`, through the same input path a keyboard takes.
static func _press(action: StringName) -> void:
	var event := InputEventAction.new()
	event.action = action
	event.pressed = true
	Input.parse_input_event(event)
	var release := InputEventAction.new()
	release.action = action
	Input.parse_input_event(release)


# Counts the frames drawn in FPS_SECONDS of play and prints the rate (the 3D board must stay
# smooth on software GL; the README quotes this number). The machine may be shared, so it
# also prints frames per second of this process's own CPU time: the rate the game would
# reach on one core of its own (software GL uses more when it has them).
static func _report_fps(tree: SceneTree, shot_name: String) -> void:
	RenderingServer.viewport_set_measure_render_time(tree.root.get_viewport_rid(), true)
	var frames := 0
	var start := Time.get_ticks_usec()
	var cpu_start := _cpu_seconds()
	while Time.get_ticks_usec() - start < int(FPS_SECONDS * 1000000.0):
		await tree.process_frame
		frames += 1
	var seconds := float(Time.get_ticks_usec() - start) / 1000000.0
	var cpu := _cpu_seconds() - cpu_start
	var size := tree.root.get_visible_rect().size
	var line := (
		"shots: %s: %.1f fps at %dx%d on %s"
		% [shot_name, frames / seconds, size.x, size.y, RenderingServer.get_video_adapter_name()]
	)
	if cpu > 0.0:
		line += ", %.1f frames per CPU second" % (frames / cpu)
	var vp := tree.root.get_viewport_rid()
	line += (
		" [process %.1f ms, physics %.1f ms, render cpu %.1f ms gpu %.1f ms]"
		% [
			Performance.get_monitor(Performance.TIME_PROCESS) * 1000.0,
			Performance.get_monitor(Performance.TIME_PHYSICS_PROCESS) * 1000.0,
			RenderingServer.viewport_get_measured_render_time_cpu(vp),
			RenderingServer.viewport_get_measured_render_time_gpu(vp),
		]
	)
	print(line)


# User + system CPU seconds this process has used (Linux); 0 where /proc is missing.
static func _cpu_seconds() -> float:
	var file := FileAccess.open("/proc/self/stat", FileAccess.READ)
	if file == null:
		return 0.0
	var text := file.get_line()  # /proc files report no length: read a line, not the size
	# the fields after the command name (which is in brackets and may hold spaces)
	var fields := text.substr(text.rfind(")") + 2).split(" ")
	if fields.size() < 13:
		return 0.0
	return (fields[11].to_float() + fields[12].to_float()) / 100.0


static func _wait(tree: SceneTree, seconds: float) -> void:
	await tree.create_timer(seconds).timeout
