extends RefCounted
## Shared steps of the replay tests: load a board, record a maze attempt the way the game
## plays it, play a replay back through a written and read file.


static func load_level(path: String) -> BoardLevel:
	return BoardLoader.load_board(path).level


## Writes and reads back: what a game file would hold.
static func round_trip(replay: Replay) -> Replay:
	var read := ReplayReader.read(ReplayWriter.write(replay))
	if not read.has("replay"):
		push_error("replay_kit: %s" % read.get("error"))
		return null
	return read["replay"]


static func play(replay: Replay, level: BoardLevel) -> Dictionary:
	return ReplayPlayer.new(round_trip(replay), level).play_to_end()


## A maze attempt played as the game plays it: a frame of uneven length, the tilt set, then
## `advance`, noted by the recorder. The tilt sweeps round so the balls travel.
static func record_live_maze(level: BoardLevel, hard: bool, frames: int) -> ReplayRecorder:
	var rules := MazeRules.new(level, hard)
	var recorder := ReplayRecorder.new()
	recorder.attach_maze(rules)
	rules.start()
	var rng := RandomNumberGenerator.new()
	rng.seed = 7
	var angle := 0.0
	for frame in frames:
		var delta := rng.randf_range(0.004, 0.04)
		angle += delta * 0.9
		rules.set_tilt(Vector2(cos(angle), sin(angle * 1.3)) * 11.87)
		rules.advance(delta)
		recorder.note_frame()
		if rules.is_over():
			break
	return recorder


## Deletes a test's replay folder and the files in it.
static func remove_folder(folder: String) -> void:
	if not DirAccess.dir_exists_absolute(folder):
		return
	for file_name in DirAccess.get_files_at(folder):
		DirAccess.remove_absolute(ProjectSettings.globalize_path(folder + "/" + file_name))
	DirAccess.remove_absolute(ProjectSettings.globalize_path(folder))
