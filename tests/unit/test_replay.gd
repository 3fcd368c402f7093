extends GutTest
## Replays: a recorded game plays back to the same state hash, for both games, whether it
## was recorded by the autoplay (one step a frame) or frame by frame with uneven frame times
## as the real games run; the file round-trips; `--replay` answers with the right exit code.

const MAZE_CLASSIC := "res://levels/maze/classic.board"
const PACHINKO_CLASSIC := "res://levels/pachinko/classic.board"
const TEMP := "user://test_replay.replay"
const ReplayKit := preload("res://tests/unit/replay_kit.gd")


class TestFormat:
	extends GutTest

	func test_a_replay_survives_writing_and_reading() -> void:
		var replay := Replay.new()
		replay.game = Replay.MAZE
		replay.board_id = "maze_classic"
		replay.board_hash = "ab".repeat(32)
		replay.rng_seed = 1776351234567
		replay.hard = true
		replay.steps = 7
		replay.state_hash = 4294967295
		replay.seconds = 0.058
		replay.records.append(["tilt", 2, 2, 1200, -1187])
		replay.records.append(["tilt", 1, 3, 0, 5])
		var text := ReplayWriter.write(replay)
		assert_eq(text, ReplayWriter.write(replay), "the same replay, the same text")
		var back: Replay = ReplayReader.read(text)["replay"]
		assert_eq(back.board_id, "maze_classic")
		assert_eq(back.board_hash, replay.board_hash)
		assert_eq(back.rng_seed, 1776351234567, "a large seed is kept exactly")
		assert_eq(back.state_hash, 4294967295)
		assert_true(back.hard)
		assert_eq(back.steps, 7)
		assert_almost_eq(back.seconds, 0.058, 0.0005)
		assert_eq(back.records, replay.records)
		assert_eq(text.count("\n"), 3, "a header line and one line per record")

	func test_packed_frames_survive_writing_and_reading() -> void:
		var replay := Replay.new()
		replay.board_id = "maze_classic"
		replay.board_hash = "cd".repeat(32)
		replay.steps = 2 + 8 + 1 + 3
		replay.records.append(["tilts", 2, 1200, -1200, 8, -1200, 1200, 1, -1199, 1187])
		replay.records.append(["tilt", 1, 3, 0, 5])
		var text := ReplayWriter.write(replay)
		assert_string_contains(text, '["tilts","')
		assert_string_contains(text, '{"replay": 4,', "files are written in format 4")
		assert_string_contains(text, '"physics": %d, "rules": 1}' % Replay.PHYSICS_VERSION)
		var read := ReplayReader.read(text)
		assert_true(read.has("replay"), str(read.get("error")))
		assert_eq((read["replay"] as Replay).records, replay.records)

	func test_a_small_tilt_change_costs_one_character() -> void:
		var record := ["tilts", 1, 500, -300]
		for frame in 100:
			record.append_array([1, 500 + frame % 7, -300 - frame % 5])
		var packed := TiltPacking.encode(record.slice(1))
		assert_lt(packed.length(), 101 * 3 + 6, "steps, x and y in a character each")
		assert_eq(TiltPacking.decode(packed)["numbers"], record.slice(1))

	func test_a_format_1_file_still_reads_and_plays() -> void:
		var level := ReplayKit.load_level(MAZE_CLASSIC)
		var replay := ReplayKit.record_live_maze(level, false, 300).finish()
		var lines := PackedStringArray()
		for record: Array in replay.records:
			for frame in Replay.frame_count(record):
				var tilt := Replay.frame_tilt(record, frame)
				var steps := Replay.frame_steps(record, frame)
				lines.append(JSON.stringify(["tilt", 1, steps, tilt.x, tilt.y]))
		var text := ReplayWriter.write(replay).get_slice("\n", 0).replace(
			'"replay": 4', '"replay": 1'
		)
		var versions := [Replay.PHYSICS_VERSION, Replay.RULES_VERSIONS["maze"]]
		text = text.replace(', "physics": %d, "rules": %d' % versions, "")
		var read := ReplayReader.read(text + "\n" + "\n".join(lines) + "\n")
		assert_true(read.has("replay"), str(read.get("error")))
		var old: Replay = read["replay"]
		assert_eq(old.format_version, 1)
		assert_eq(old.physics_version, 1, "files before format 3 were recorded with physics 1")
		old.physics_version = Replay.PHYSICS_VERSION  # recorded just now, by this build
		old.rules_version = Replay.RULES_VERSIONS["maze"]
		var played := ReplayPlayer.new(old, level).play_to_end()
		assert_true(played["match"], str(played))

	func test_the_best_run_and_last_game_paths() -> void:
		assert_eq(
			ReplayStore.best_maze_path("maze_classic", true),
			"user://replays/maze_classic_hard.replay"
		)
		assert_eq(
			ReplayStore.best_maze_path("my board/..", false),
			"user://replays/maze_my_board____easy.replay"
		)
		assert_eq(
			ReplayStore.last_pachinko_path("pachinko_tulips"),
			"user://replays/pachinko_tulips_last.replay"
		)

	func test_tilt_and_power_are_kept_in_hundredths() -> void:
		var rules := MazeRules.new(ReplayKit.load_level(MAZE_CLASSIC))
		rules.set_tilt(Vector2(1.23456, -7.891))
		assert_almost_eq(rules.tilt.x, 1.23, 0.00001)
		assert_almost_eq(rules.tilt.y, -7.89, 0.00001)
		var again := rules.tilt
		rules.set_tilt(Vector2(123, -789) / 100.0)
		assert_eq(rules.tilt, again, "the hundredths a file holds give the very same tilt")


class TestMaze:
	extends GutTest

	func test_an_autoplay_run_replays_to_the_same_state_hash() -> void:
		var level := ReplayKit.load_level(MAZE_CLASSIC)
		var recorder := ReplayRecorder.new()
		var result := MazeAutoplay.run(level, 20.0, 1, false, recorder)
		var replay := recorder.finish()
		assert_eq(replay.state_hash, int(result["state_hash"]), "recorded at the autoplay's end")
		assert_eq(replay.steps, int(result["frames_simulated"]))
		var played := ReplayKit.play(replay, level)
		assert_true(played["match"], str(played))
		assert_eq(played["state_hash"], result["state_hash"])

	func test_a_game_with_uneven_frames_replays_exactly() -> void:
		var level := ReplayKit.load_level(MAZE_CLASSIC)
		var replay := ReplayKit.record_live_maze(level, false, 900).finish()
		assert_gt(replay.steps, 900, "frames of several steps were recorded")
		var played := ReplayKit.play(replay, level)
		assert_true(played["match"], str(played))

	func test_a_hard_run_lost_in_a_hole_replays_exactly() -> void:
		var level := ReplayKit.load_level(MAZE_CLASSIC)
		var recorder := ReplayKit.record_live_maze(level, true, 3000)
		var replay := recorder.finish()
		assert_true(replay.hard)
		var played := ReplayKit.play(replay, level)
		assert_true(played["match"], str(played))

	func test_a_minute_of_play_is_a_small_file() -> void:
		var recorder := ReplayRecorder.new()
		MazeAutoplay.run(ReplayKit.load_level(MAZE_CLASSIC), 60.0, 2, false, recorder)
		var text := ReplayWriter.write(recorder.finish())
		assert_lt(text.length(), 40 * 1024, "a minute at 120 steps a second, run-length encoded")

	func test_a_minute_of_tilt_changing_every_frame_is_a_small_file() -> void:
		var level := ReplayKit.load_level(MAZE_CLASSIC)
		var rules := MazeRules.new(level)
		var recorder := ReplayRecorder.new()
		recorder.attach_maze(rules)
		rules.start()
		var frames := roundi(60.0 / rules.step_seconds())
		for frame in frames:
			var angle := frame * 0.01
			rules.set_tilt(Vector2(cos(angle), sin(angle * 1.3)) * 11.87)
			rules.step()
			recorder.note_frame()
		var replay := recorder.finish()
		assert_eq(replay.steps, frames, "the run lasted the whole minute")
		var text := ReplayWriter.write(replay)
		assert_lt(text.length(), 40 * 1024, "%d frames, each with its own tilt" % frames)
		var played := ReplayKit.play(replay, level)
		assert_true(played["match"], str(played))


class TestPachinko:
	extends GutTest

	func test_an_autoplay_game_replays_to_the_same_state_hash() -> void:
		var level := ReplayKit.load_level(PACHINKO_CLASSIC)
		var recorder := ReplayRecorder.new()
		var result := PachinkoAutoplay.run(level, 40.0, 3, recorder)
		var replay := recorder.finish()
		assert_eq(replay.state_hash, int(result["state_hash"]))
		assert_gt(int(result["shots"]), 10)
		var played := ReplayKit.play(replay, level)
		assert_true(played["match"], str(played))

	func test_charged_shots_with_uneven_frames_replay_exactly() -> void:
		var level := ReplayKit.load_level(PACHINKO_CLASSIC)
		var rules := PachinkoRules.new(level, 99)
		var recorder := ReplayRecorder.new()
		recorder.attach_pachinko(rules, 99)
		var rng := RandomNumberGenerator.new()
		rng.seed = 11
		rules.start_game()
		var holding := 0.0
		for frame in 1500:
			var delta := rng.randf_range(0.005, 0.035)
			if not rules.drawing and rules.loaded and rng.randf() < 0.05:
				rules.begin_charge()
				holding = rng.randf_range(0.3, 1.3)
			elif rules.drawing:
				rules.charge(delta)
				holding -= delta
				if holding <= 0.0:
					rules.release()
			rules.advance(delta)
			recorder.note_frame()
		var replay := recorder.finish()
		assert_gt(rules.ledger.shots, 5, "shots were fired")
		var played := ReplayKit.play(replay, level)
		assert_true(played["match"], str(played))


class TestCommand:
	extends GutTest

	func before_each() -> void:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(TEMP))

	func after_all() -> void:
		DirAccess.remove_absolute(ProjectSettings.globalize_path(TEMP))

	func _recorded() -> Replay:
		var recorder := ReplayRecorder.new()
		MazeAutoplay.run(ReplayKit.load_level(MAZE_CLASSIC), 5.0, 1, false, recorder)
		return recorder.finish()

	func test_a_matching_replay_exits_0() -> void:
		assert_eq(ReplayStore.save(_recorded(), TEMP), OK)
		assert_eq(ReplayCli.run({"replay": TEMP}), 0)

	func test_a_wrong_final_hash_exits_1() -> void:
		var replay := _recorded()
		replay.state_hash += 1
		ReplayStore.save(replay, TEMP)
		assert_eq(ReplayCli.run({"replay": TEMP}), 1)

	func test_a_changed_board_exits_2_and_says_so() -> void:
		var replay := _recorded()
		replay.board_hash = "0".repeat(64)
		ReplayStore.save(replay, TEMP)
		assert_eq(ReplayCli.run({"replay": TEMP}), 2)
		var found := ReplayStore.find_board(replay)
		assert_string_contains(str(found.get("error")), "has changed since the replay was recorded")

	func test_a_run_from_another_physics_version_exits_2_naming_both() -> void:
		var replay := _recorded()
		replay.physics_version = Replay.PHYSICS_VERSION + 1
		ReplayStore.save(replay, TEMP)
		var read: Replay = ReplayStore.read_file(TEMP)["replay"]
		assert_eq(read.physics_version, Replay.PHYSICS_VERSION + 1, "read back as written")
		assert_eq(ReplayCli.run({"replay": TEMP}), 2)
		assert_string_contains(
			read.physics_problem(),
			(
				"recorded with physics version %d and this game runs version %d"
				% [Replay.PHYSICS_VERSION + 1, Replay.PHYSICS_VERSION]
			)
		)

	func test_a_pachinko_run_from_the_rules_before_aimed_launches_exits_2_naming_both() -> void:
		var level := ReplayKit.load_level(PACHINKO_CLASSIC)
		var rules := PachinkoRules.new(level, 1)
		var recorder := ReplayRecorder.new()
		recorder.attach_pachinko(rules, 1)
		rules.start_game()
		rules.fire(50.0)
		for i in 30:
			rules.advance(1.0 / 60.0)
			recorder.note_frame()
		var replay := recorder.finish()
		var now: int = Replay.RULES_VERSIONS["pachinko"]
		assert_eq(replay.rules_version, now, "pachinko runs are recorded under this game's rules")
		var text := ReplayWriter.write(replay)
		var old_text := text.replace(', "rules": %d' % now, "").replace(
			'"replay": 4', '"replay": 3'
		)
		var old: Replay = ReplayReader.read(old_text)["replay"]
		assert_eq(old.rules_version, 1, "files before format 4 were recorded with rules 1")
		assert_string_contains(
			old.physics_problem(),
			"recorded with pachinko rules version 1 and this game plays version %d" % now
		)
		var file := FileAccess.open(TEMP, FileAccess.WRITE)
		file.store_string(old_text)
		file.close()
		assert_eq(ReplayCli.run({"replay": TEMP}), 2, "refused, not replayed into another game")
		assert_eq(ReplayStore.read_file(TEMP)["replay"].physics_problem(), old.physics_problem())

	func test_the_physics_field_belongs_to_format_3_and_up() -> void:
		var header := ReplayWriter.write(_recorded()).get_slice("\n", 0)
		var physics := ', "physics": %d' % Replay.PHYSICS_VERSION
		var rules := ', "rules": %d' % Replay.RULES_VERSIONS["maze"]
		var cases := {
			header.replace(physics, ""): 'the header has no "physics"',
			header.replace('"replay": 4', '"replay": 2').replace(rules, ""):
			'"physics" came with format 3',
			header.replace('"replay": 4', '"replay": 3'): '"rules" came with format 4',
			header.replace(rules, ""): 'the header has no "rules"',
			header.replace(rules, ', "rules": 0'): '"rules" must be a whole number from 1',
			header.replace(physics, ', "physics": 0'):
			'"physics" must be a whole number from 1 to 1000',
			header.replace(physics, ', "physics": "2"'):
			'"physics" must be a whole number from 1 to 1000',
			header.replace(physics, ', "physics": 1e300'):
			'"physics" must be a whole number from 1 to 1000',
		}
		for text: String in cases:
			var error := str(ReplayReader.read(text + "\n").get("error"))
			assert_string_contains(error, cases[text], text)

	func test_a_missing_board_or_file_exits_2() -> void:
		var replay := _recorded()
		replay.board_id = "no_such_board"
		ReplayStore.save(replay, TEMP)
		assert_eq(ReplayCli.run({"replay": TEMP}), 2)
		assert_string_contains(
			str(ReplayStore.find_board(replay).get("error")), "no maze board 'no_such_board'"
		)
		assert_eq(ReplayCli.run({"replay": "user://no_such.replay"}), 2)


class TestLimits:
	extends GutTest

	func test_a_game_too_long_for_a_file_stops_recording_and_saves_nothing() -> void:
		var rules := PachinkoRules.new(ReplayKit.load_level(PACHINKO_CLASSIC), 1)
		var recorder := ReplayRecorder.new()
		recorder.attach_pachinko(rules, 1)
		rules.world.step_count = ReplayReader.MAX_STEPS + 1  # as after hours of play
		recorder.note_frame()
		assert_false(recorder.is_recording())
		assert_null(recorder.finish(), "no replay the reader would refuse")
		assert_eq(ReplayStore.save(recorder.finish(), "user://never.replay"), ERR_INVALID_PARAMETER)
		assert_false(FileAccess.file_exists("user://never.replay"))


class TestPachinkoScreen:
	extends GutTest

	const GAME := preload("res://scenes/pachinko/pachinko_game.tscn")
	const FOLDER := "user://test_replay_pachinko"

	func before_each() -> void:
		ReplayStore.folder = FOLDER

	func after_each() -> void:
		ReplayKit.remove_folder(FOLDER)
		ReplayStore.folder = ReplayStore.DIR

	func test_the_screen_keeps_the_last_game_as_a_replay_that_plays_back() -> void:
		var game: PachinkoGame = GAME.instantiate()
		add_child_autofree(game)
		var rules: PachinkoRules = game.get("rules")
		for frame in 20:
			game._process(1.0 / 60.0)
		rules.start_game()
		for shot in 4:
			rules.begin_charge()
			rules.charge(0.55 + 0.137 * shot)
			rules.release()
			for frame in 40:
				game._process(1.0 / 60.0)
		assert_eq(rules.ledger.shots, 4, "four charged shots")
		game._on_game_ended(rules.stats())
		var path := ReplayStore.last_pachinko_path(rules.level.board_id)
		assert_eq(path, FOLDER + "/pachinko_classic_last.replay")
		var read := ReplayStore.read_file(path)
		assert_true(read.has("replay"), str(read.get("error")))
		var played := ReplayPlayer.new(read["replay"], rules.level).play_to_end()
		assert_true(played["match"], str(played))
		assert_eq(played["state_hash"], rules.world.state_hash(), "the screen's own game")
