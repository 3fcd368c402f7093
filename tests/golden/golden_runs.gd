extends RefCounted
## The runs whose state hashes pin the physics bit for bit (issue 43): the bench scenes
## S1-S5 after SCENE_STEPS steps on 1 and 2 threads, every shipped board's autoplay
## (pachinko AUTOPLAY_SECONDS[0] s, maze [1] s, seed 1) and a recorded replay of each game
## played back. tests/golden/golden_hashes.json holds what they gave; test_golden_hashes.gd
## compares, tests/golden/record_golden.gd (make golden) writes it anew.

const BenchScenes := preload("res://tests/bench/physics/bench_scenes.gd")
const OursRunner := preload("res://tests/bench/physics/ours_runner.gd")
const TABLE_PATH := "res://tests/golden/golden_hashes.json"
## name, mode, pin pitch, balls, hz: the bench's scenes (tests/bench/bench_physics.gd).
const SCENES := [
	["S1", "flow", 24.0, 1000, 240.0],
	["S2", "pile", 24.0, 3000, 240.0],
	["S3", "fast", 12.0, 500, 60.0],
	["S4", "maze", 0.0, 1000, 120.0],
	["S5", "windmills", 24.0, 1000, 120.0],
]
const SCENE_STEPS := 200
const THREADS: Array[int] = [1, 2]
## Seconds of autoplay: pachinko, maze (BoardLevel.Kind order).
const AUTOPLAY_SECONDS: Array[float] = [60.0, 30.0]
const AUTOPLAY_SEED := 1
## The replays played back: game -> file (recorded by record_golden.gd on the classic boards).
const REPLAYS := {
	"pachinko": "res://tests/golden/pachinko_classic.replay",
	"maze": "res://tests/golden/maze_classic.replay",
}
## Seconds each golden replay records.
const REPLAY_SECONDS := 10.0


## The versions a table's hashes belong to: BallWorld.PHYSICS_VERSION and each game's
## rules version. A hash may change only when one of them does.
static func versions() -> Dictionary:
	return {"physics": BallWorld.PHYSICS_VERSION, "rules": Replay.RULES_VERSIONS.duplicate()}


## Every run's name, in the table's order.
static func names() -> PackedStringArray:
	var out := PackedStringArray()
	for scene: Array in SCENES:
		for threads in THREADS:
			out.append("%s %d steps, %d thread%s" % [scene[0], SCENE_STEPS, threads, _s(threads)])
	for kind in [BoardLevel.Kind.PACHINKO, BoardLevel.Kind.MAZE]:
		for board_id in _shipped_boards(kind):
			out.append(_autoplay_name(kind, board_id))
	for game: String in REPLAYS:
		out.append("%s replay" % game)
	return out


## The state hash run `name` gives now (names() lists them).
static func hash_of(name: String) -> int:
	for scene: Array in SCENES:
		for threads in THREADS:
			if name == "%s %d steps, %d thread%s" % [scene[0], SCENE_STEPS, threads, _s(threads)]:
				var made: Dictionary = BenchScenes.make(
					scene[0], scene[1], scene[2], scene[3], scene[4]
				)
				return OursRunner.run(made, SCENE_STEPS, false, true, threads)["hash"]
	for kind in [BoardLevel.Kind.PACHINKO, BoardLevel.Kind.MAZE]:
		for board_id in _shipped_boards(kind):
			if name == _autoplay_name(kind, board_id):
				return _autoplay_hash(kind, board_id)
	for game: String in REPLAYS:
		if name == "%s replay" % game:
			return replay_hash(REPLAYS[game])
	push_error("GoldenRuns: no run named '%s'" % name)
	return 0


## The state hash a replay file plays back to (0 when it cannot be played: see the error).
static func replay_hash(path: String) -> int:
	var read := ReplayStore.read_file(path)
	if read.has("error"):
		push_error(str(read["error"]))
		return 0
	var replay: Replay = read["replay"]
	var board := ReplayStore.find_board(replay)
	if board.has("error"):
		push_error("%s: %s" % [path, board["error"]])
		return 0
	var player := ReplayPlayer.new(replay, board["level"])
	return player.play_to_end()["state_hash"]


## Records the golden replay of `game` (its classic board, REPLAY_SECONDS of autoplay) into
## REPLAYS[game]; returns the problem, or "" when written.
static func record_replay(game: String) -> String:
	var kind := BoardLevel.kind_named(game)
	var level := BoardLoader.load_board("res://levels/%s/classic.board" % game).level
	var recorder := ReplayRecorder.new()
	if kind == BoardLevel.Kind.MAZE:
		MazeAutoplay.run(level, REPLAY_SECONDS, AUTOPLAY_SEED, false, recorder)
	else:
		PachinkoAutoplay.run(level, REPLAY_SECONDS, AUTOPLAY_SEED, recorder)
	var error := ReplayStore.save(recorder.finish(), REPLAYS[game])
	return "" if error == OK else "%s: %s" % [REPLAYS[game], error_string(error)]


static func _autoplay_name(kind: BoardLevel.Kind, board_id: String) -> String:
	var seconds := AUTOPLAY_SECONDS[kind]
	return "%s %s autoplay %d s" % [BoardLevel.kind_name(kind), board_id, int(seconds)]


static func _autoplay_hash(kind: BoardLevel.Kind, board_id: String) -> int:
	var game := BoardLevel.kind_name(kind)
	var level := BoardLoader.load_board("res://levels/%s/%s.board" % [game, board_id]).level
	var seconds := AUTOPLAY_SECONDS[kind]
	var result: Dictionary
	if kind == BoardLevel.Kind.MAZE:
		result = MazeAutoplay.run(level, seconds, AUTOPLAY_SEED, false)
	else:
		result = PachinkoAutoplay.run(level, seconds, AUTOPLAY_SEED)
	return result["state_hash"]


# The shipped boards of a game by file name, sorted.
static func _shipped_boards(kind: BoardLevel.Kind) -> PackedStringArray:
	var folder := "res://levels/%s" % BoardLevel.kind_name(kind)
	var ids := PackedStringArray()
	for file_name in DirAccess.get_files_at(folder):
		if file_name.ends_with(".board"):
			ids.append(file_name.get_basename())
	ids.sort()
	return ids


static func _s(count: int) -> String:
	return "" if count == 1 else "s"
