extends GutTest
## The ghost of the best run: a saved best maze run played in its own world, in step with a
## live attempt, shows the balls where the best run had them at the same step; the maze
## screen saves a best run and shows its ghost on the next attempt.

const MAZE_CLASSIC := "res://levels/maze/classic.board"
const ReplayKit := preload("res://tests/unit/replay_kit.gd")
const GAME := preload("res://scenes/maze/maze_game.tscn")
const TEST_FOLDER := "user://test_replay_ghost"
const TEST_SETTINGS := "user://test_ghost_settings.cfg"
const TEST_SAVE := "user://test_ghost_save.cfg"


func before_each() -> void:
	ReplayStore.folder = TEST_FOLDER
	ReplayKit.remove_folder(TEST_FOLDER)


func after_each() -> void:
	ReplayKit.remove_folder(TEST_FOLDER)
	ReplayStore.folder = ReplayStore.DIR


## A first attempt played frame by frame as the game does; returns the replay and the ball
## positions after every frame, by step count.
func _first_attempt(level: BoardLevel) -> Array:
	var rules := MazeRules.new(level)
	var recorder := ReplayRecorder.new()
	recorder.attach_maze(rules)
	rules.start()
	var seen := {}
	var rng := RandomNumberGenerator.new()
	rng.seed = 5
	var angle := 0.0
	for frame in 600:
		var delta := rng.randf_range(0.006, 0.03)
		angle += delta
		rules.set_tilt(Vector2(cos(angle), sin(angle * 1.7)) * 12.0)
		rules.advance(delta)
		recorder.note_frame()
		seen[rules.world.step_count] = rules.world.get_positions()
	return [recorder.finish(), seen]


func test_the_ghost_shows_the_best_run_step_for_step() -> void:
	var level := ReplayKit.load_level(MAZE_CLASSIC)
	var first := _first_attempt(level)
	var replay: Replay = first[0]
	var seen: Dictionary = first[1]
	assert_eq(ReplayStore.save(replay, ReplayStore.best_maze_path(level.board_id, false)), OK)
	var ghost := GhostRun.load_best(level, false)
	assert_not_null(ghost, "the second attempt finds the best run")
	assert_eq(
		ghost.positions(), ReplayKit.load_level(MAZE_CLASSIC).ball_starts, "it waits at the start"
	)
	var compared := 0
	var live_steps := 0
	while live_steps < replay.steps:
		live_steps += 1 + (live_steps % 3)  # the live game's own, different frames
		ghost.sync(live_steps)
		assert_lte(ghost.steps(), live_steps, "the ghost never runs ahead")
		if seen.has(ghost.steps()):
			assert_eq(ghost.positions(), seen[ghost.steps()], "step %d" % ghost.steps())
			compared += 1
	assert_gt(compared, 100, "positions were compared all along the run")
	ghost.sync(replay.steps + 1000)
	assert_true(ghost.is_finished())
	assert_eq(ghost.positions(), seen[replay.steps], "it stays where the best run ended")
	ghost.restart()
	assert_eq(ghost.steps(), 0, "a reset sends it back to the start")


func test_no_ghost_without_a_best_run_in_that_mode_for_a_changed_board_or_physics() -> void:
	var level := ReplayKit.load_level(MAZE_CLASSIC)
	assert_null(GhostRun.load_best(level, false), "nothing saved yet")
	var replay: Replay = _first_attempt(level)[0]
	ReplayStore.save(replay, ReplayStore.best_maze_path(level.board_id, false))
	assert_null(GhostRun.load_best(level, true), "the easy run is no ghost for hard mode")
	replay.board_hash = "f".repeat(64)
	ReplayStore.save(replay, ReplayStore.best_maze_path(level.board_id, false))
	assert_null(GhostRun.load_best(level, false), "the board changed since: no ghost")
	replay.board_hash = Replay.content_hash(level)
	replay.physics_version = Replay.PHYSICS_VERSION + 1
	ReplayStore.save(replay, ReplayStore.best_maze_path(level.board_id, false))
	assert_null(GhostRun.load_best(level, false), "another physics version rolls differently")
	replay.physics_version = Replay.PHYSICS_VERSION
	ReplayStore.save(replay, ReplayStore.best_maze_path(level.board_id, false))
	assert_not_null(GhostRun.load_best(level, false), "the same run under this physics: a ghost")


func test_the_ghost_setting_is_saved_and_read_back() -> void:
	var path := "user://test_ghost_setting.cfg"
	var settings := GameSettings.new()
	assert_true(settings.show_ghost, "on by default")
	settings.set_value("show_ghost", false)
	assert_eq(settings.save_file(path), OK)
	var read := GameSettings.new()
	assert_eq(read.load_file(path), "", "no problem reported")
	assert_false(read.show_ghost)
	DirAccess.remove_absolute(ProjectSettings.globalize_path(path))


class TestMazeScreen:
	extends GutTest

	var _game: MazeGame

	func before_all() -> void:
		App.load_player_files(TEST_SETTINGS, TEST_SAVE)

	func after_all() -> void:
		App.load_player_files(App.SETTINGS_PATH, App.SAVE_PATH)
		for path in [TEST_SETTINGS, TEST_SAVE]:
			DirAccess.remove_absolute(ProjectSettings.globalize_path(path))

	func before_each() -> void:
		ReplayStore.folder = TEST_FOLDER
		ReplayKit.remove_folder(TEST_FOLDER)
		_game = GAME.instantiate()
		add_child_autofree(_game)

	func after_each() -> void:
		ReplayKit.remove_folder(TEST_FOLDER)
		ReplayStore.folder = ReplayStore.DIR

	func _rules() -> MazeRules:
		return _game.rules

	## Plays an attempt through the screen as a player would: the joystick moved each frame
	## (by the autoplay's pilot) and the screen's own `_process`. Returns positions by step.
	func _play_attempt(frames: int) -> Dictionary:
		var rules := _rules()
		var mixer: TiltMixer = _game.mixer
		var rng := RandomNumberGenerator.new()
		rng.seed = 1
		var pilot := MazePilot.new(rules.level, false, rng, rules.step_seconds())
		_game._start()
		var seen := {}
		for frame in frames:
			var tilt := pilot.decide(rules.world.get_positions(), rules.world.get_velocities())
			mixer.joystick_moved(TiltInput.joystick_from_tilt(tilt))
			_game._process(1.0 / 60.0)
			seen[rules.world.step_count] = rules.world.get_positions()
			if rules.is_over():
				break
		return seen

	# Trial 7: a see-through ball stood still on the start spot of a first try ("Best --"):
	# a replay file was there (an earlier save's) but no best time. No best time, no ghost.
	func test_no_ghost_from_a_replay_file_without_a_best_time() -> void:
		var rules := _rules()
		assert_lt(App.best_maze_time(rules.level.board_id, false), 0.0, "a fresh save")
		var replay: Replay = ReplayKit.record_live_maze(rules.level, false, 200).finish()
		ReplayStore.save(replay, ReplayStore.best_maze_path(rules.level.board_id, false))
		rules.reset()
		assert_eq(_game.ghost(), null, "no ghost before the player has a best time")

	func test_a_best_run_is_saved_and_its_ghost_shows_on_the_next_attempt() -> void:
		var rules := _rules()
		var path := ReplayStore.best_maze_path(rules.level.board_id, false)
		assert_eq(_game.ghost(), null, "no ghost before any best run")
		var first := _play_attempt(60 * 120)
		assert_eq(rules.state, MazeRules.State.WON, "the pilot won the first attempt")
		assert_true(FileAccess.file_exists(path), "the best run was saved")
		var saved: Replay = ReplayStore.read_file(path)["replay"]
		assert_true(ReplayKit.play(saved, rules.level)["match"], "and it replays to its own end")
		rules.reset()
		var ghost: GhostRun = _game.ghost()
		assert_not_null(ghost, "the second attempt has a ghost")
		_game._start()
		for frame in 90:
			_game._process(1.0 / 60.0)
		assert_gt(ghost.steps(), 100, "the ghost kept pace with the live game")
		assert_eq(ghost.positions(), first[ghost.steps()], "where the best run was")
		var view: Node3D = _game.ghost_view()
		assert_eq(view.get("shown_positions"), ghost.positions(), "the ghost view draws them")

	func test_the_setting_turns_the_ghost_off() -> void:
		App.settings.set_value("show_ghost", false)
		var rules := _rules()
		var replay: Replay = ReplayKit.record_live_maze(rules.level, false, 200).finish()
		ReplayStore.save(replay, ReplayStore.best_maze_path(rules.level.board_id, false))
		rules.reset()
		assert_eq(_game.ghost(), null, "no ghost when the setting is off")
		App.settings.set_value("show_ghost", true)
		rules.reset()
		assert_not_null(_game.ghost(), "and back when it is on")
		var note := str(_game.get_node("%Note").text())
		assert_string_contains(
			note, "See-through blue balls replay your best run", "the ghost is named"
		)

	# Trial 5 saw the ghost roll on behind the finish card: after the win the world settles
	# the live balls (its steps go on), and the ghost followed those steps. It stops there.
	func test_the_ghost_stops_at_the_finish() -> void:
		var rules := _rules()
		var replay: Replay = ReplayKit.record_live_maze(rules.level, false, 600).finish()
		ReplayStore.save(replay, ReplayStore.best_maze_path(rules.level.board_id, false))
		rules.reset()
		var ghost: GhostRun = _game.ghost()
		assert_not_null(ghost, "a ghost to watch")
		_game._start()
		for frame in 30:
			_game._process(1.0 / 60.0)
		var spots := [Vector2(-7, -7), Vector2(7, -7), Vector2(-7, 7), Vector2(7, 7)]
		var ids := rules.world.get_ids()
		for i in ids.size():
			rules.world.set_ball_position(ids[i], rules.level.goal_center + spots[i % 4])
			rules.world.set_ball_velocity(ids[i], Vector2.ZERO)
		_game._process(1.0 / 60.0)
		assert_eq(rules.state, MazeRules.State.WON, "won")
		var at_finish := ghost.steps()
		var view: Node3D = _game.ghost_view()
		var shown: Variant = view.get("shown_positions")
		for frame in 60:
			_game._process(1.0 / 60.0)
		assert_gt(rules.world.step_count, at_finish + 100, "the live balls settle on")
		assert_eq(ghost.steps(), at_finish, "the ghost stays where the finish found it")
		assert_eq(view.get("shown_positions"), shown, "and is drawn there")


# A play trial's note: a player's saved ghosts stopped loading each time a board's medal
# times were re-measured, because the replay kept the hash of the whole board text.
func test_a_ghost_survives_new_medal_times_and_a_new_name_but_not_a_new_layout() -> void:
	var level := ReplayKit.load_level(MAZE_CLASSIC)
	var replay: Replay = _first_attempt(level)[0]
	assert_eq(replay.board_hash, Replay.board_hash_of(level), "a new replay keeps the play hash")
	ReplayStore.save(replay, ReplayStore.best_maze_path(level.board_id, false))
	var remeasured := ReplayKit.load_level(MAZE_CLASSIC)
	remeasured.medal_times_easy = PackedFloat64Array([11.0, 19.8, 38.5])
	remeasured.display_name = "Classic, renamed"
	assert_ne(Replay.content_hash(remeasured), Replay.content_hash(level), "the file did change")
	assert_not_null(GhostRun.load_best(remeasured, false), "new medal times keep the ghost")
	var moved := ReplayKit.load_level(MAZE_CLASSIC)
	var walls := moved.walls
	walls[0] += Vector2(4.0, 0.0)
	moved.walls = walls
	assert_null(GhostRun.load_best(moved, false), "a wall moved: the run no longer plays there")
	assert_false(replay.recorded_on(moved))
	assert_true(ReplayStore.find_board(replay).has("level"), "the replay finds its board")


func test_a_ghost_recorded_with_the_whole_boards_hash_still_plays() -> void:
	var level := ReplayKit.load_level(MAZE_CLASSIC)
	var replay: Replay = _first_attempt(level)[0]
	replay.board_hash = Replay.content_hash(level)  # as every replay before play hashes
	ReplayStore.save(replay, ReplayStore.best_maze_path(level.board_id, false))
	assert_not_null(GhostRun.load_best(level, false), "an older replay of the same board plays")
