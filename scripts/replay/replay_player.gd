class_name ReplayPlayer
extends RefCounted
## Plays a Replay back through the same rules on the same board, frame by frame: the maze
## from `MazeRules.start()`, pachinko from fresh `PachinkoRules` with the recorded seed.
## `play_to_end()` runs it all (the `--replay` command); `advance_to()` runs whole frames up to
## a step count (the ghost keeps pace with a live game with it). The caller checks the board
## first: the level must be the one whose content hash the replay names.

## What was played.
var replay: Replay
## The maze rules being played (null for pachinko).
var maze: MazeRules
## The pachinko rules being played (null for the maze).
var pachinko: PachinkoRules
## Why the playback left the recording ("" while it follows it): a shot that could not be
## fired, a game that would not start, or a maze run that ended before its recorded frames.
var diverged := ""

var _record := 0
## The frame of the current record played next.
var _frame := 0


## Builds the rules for `replay` on `level` and starts the maze attempt.
func _init(played: Replay, level: BoardLevel) -> void:
	replay = played
	if replay.game == Replay.MAZE:
		maze = MazeRules.new(level, replay.hard)
		maze.start()
	else:
		pachinko = PachinkoRules.new(level, replay.rng_seed)


## The world being played.
func world() -> BallWorld:
	return maze.world if maze != null else pachinko.world


## Fixed steps run so far.
func steps() -> int:
	var played := world()
	return played.step_count if played != null else 0


## True when every record was played (or the playback diverged and stopped).
func is_done() -> bool:
	return _record >= replay.records.size() or not diverged.is_empty()


## Plays every record left. Returns steps, state_hash, the recorded ones and whether they
## match (and `diverged` when the playback left the recording).
func play_to_end() -> Dictionary:
	while not is_done():
		_play_next()
	var result := {
		"steps": steps(),
		"state_hash": world().state_hash() if world() != null else 0,
		"recorded_steps": replay.steps,
		"recorded_hash": replay.state_hash,
	}
	result["match"] = (
		diverged.is_empty()
		and result["steps"] == replay.steps
		and result["state_hash"] == replay.state_hash
	)
	if not diverged.is_empty():
		result["diverged"] = diverged
	return result


## Plays whole frames (and the events before them) while the step count stays within
## `target_steps`; the playback never runs ahead of it.
func advance_to(target_steps: int) -> void:
	while not is_done():
		var next := _next_frame_steps()
		if next > 0 and steps() + next > target_steps:
			return
		_play_next()


# Steps of the next frame when the next record is a frame record, 0 when it is an event.
func _next_frame_steps() -> int:
	var record: Array = replay.records[_record]
	if Replay.frame_count(record) == 0:
		return 0
	return Replay.frame_steps(record, _frame)


# Plays one event, or the next frame of a frame record.
func _play_next() -> void:
	var record: Array = replay.records[_record]
	var kind: String = record[0]
	var frames := Replay.frame_count(record)
	if frames > 0:
		_play_frame(record, _frame)
		_frame += 1
		if _frame == frames:
			_frame = 0
			_record += 1
		return
	_record += 1
	if kind == "start" and not pachinko.start_game():
		diverged = "the game could not start at step %d" % steps()
	elif kind == "fire" and pachinko.fire(_hundredths(record[2])) < 0:
		diverged = "the shot at step %d could not be fired" % steps()
	elif kind == "house":
		pachinko.bonus.grant_house_jackpot()


func _play_frame(record: Array, frame: int) -> void:
	var count := Replay.frame_steps(record, frame)
	if maze == null:
		pachinko.run_steps(count)
		return
	var tilt := Replay.frame_tilt(record, frame)
	maze.set_tilt(Vector2(_hundredths(tilt.x), _hundredths(tilt.y)))
	if maze.run_steps(count) == 0:
		diverged = "the run ended at step %d, before the recording did" % steps()


static func _hundredths(whole: Variant) -> float:
	var number: int = whole
	return float(number) / Replay.HUNDREDTHS
