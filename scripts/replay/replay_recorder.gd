class_name ReplayRecorder
extends RefCounted
## Records a game as it is played, for a Replay: attach it to the rules, call `note_frame()`
## after every frame that advanced them, and `finish()` when a replay is wanted.
##
## The maze records one attempt: from `MazeRules.started` until the next reset, the tilt of
## every frame and how many fixed steps it ran. Pachinko records the rules' whole life (its
## world never restarts): the steps of every frame, each game start and each shot's power.
## Frames matter, not just steps: the rules check wins and stuck balls once per frame, so a
## replay runs the same steps in the same frames.

## Frames of one tilt in a row that are worth a "tilt" record of their own (a line of about
## 25 characters) rather than three packed digits each.
const HELD_FRAMES := 10

var _maze: MazeRules
var _pachinko: PachinkoRules
var _replay := Replay.new()
## World step count when the last frame was noted.
var _noted_steps := 0
var _recording := false
## True once the recording grew past what a replay file may hold (ReplayReader's caps).
var _too_long := false


## Records attempts on `rules` (each from its start until a reset). `rng_seed` is stored
## for reference (the maze has no randomness of its own).
func attach_maze(rules: MazeRules, rng_seed := 0) -> void:
	_maze = rules
	_begin(rules.level, rng_seed, rules.step_seconds())
	rules.started.connect(_on_maze_started)
	rules.game_reset.connect(_on_maze_reset)
	if rules.is_playing():
		_on_maze_started()


## Records everything `rules` does from now on; it must be fresh (its world not stepped
## yet). `rng_seed` must be the seed the rules were built with.
func attach_pachinko(rules: PachinkoRules, rng_seed: int) -> void:
	_pachinko = rules
	_begin(rules.level, rng_seed, rules.step_seconds())
	if rules.world.step_count != 0:
		push_error("ReplayRecorder: attach to fresh PachinkoRules, before any step")
	rules.game_started.connect(_on_pachinko_started)
	rules.ball_launched.connect(_on_ball_launched)
	rules.bonus.house_jackpot_granted.connect(_on_house_granted)
	_recording = true


## True while frames are being recorded (a maze attempt is under way).
func is_recording() -> bool:
	return _recording


## Notes the frame that just ran: the steps since the last note (none: nothing to note) and,
## in the maze, the tilt they ran with.
func note_frame() -> void:
	if not _recording:
		return
	var world := _world()
	if (
		world.step_count > ReplayReader.MAX_STEPS
		or _replay.records.size() >= ReplayReader.MAX_LINES - 1
	):
		push_warning("ReplayRecorder: the game is too long for a replay; recording stopped")
		_recording = false
		_too_long = true
		return
	var steps := world.step_count - _noted_steps
	_noted_steps = world.step_count
	while steps > 0:
		# The world runs at most MAX_STEPS_PER_FRAME a frame; more means frames were missed.
		var chunk := mini(steps, ReplayReader.MAX_STEPS_PER_FRAME)
		if steps > chunk:
			push_warning("ReplayRecorder: %d steps in one frame; a frame was not noted" % steps)
		_add_frame(chunk)
		steps -= chunk


## The replay so far, ended here (the pending frame noted, the state hash taken now). The
## recorder goes on recording; null before a maze attempt started or when the game grew
## too long for a replay file.
func finish() -> Replay:
	if (_maze == null and _pachinko == null) or _too_long:
		return null
	if _maze != null and _replay.records.is_empty() and not _recording:
		return null
	note_frame()
	var done := Replay.new()
	done.game = _replay.game
	done.rules_version = Replay.rules_version_of(done.game)
	done.board_id = _replay.board_id
	done.board_hash = _replay.board_hash
	done.rng_seed = _replay.rng_seed
	done.step_hz = _replay.step_hz
	done.hard = _maze.hard_mode if _maze != null else false
	done.steps = _world().step_count
	done.state_hash = _world().state_hash()
	done.seconds = _maze.elapsed if _maze != null else 0.0
	for record in _replay.records:
		done.records.append(record.duplicate())
	return done


func _begin(level: BoardLevel, rng_seed: int, step_seconds: float) -> void:
	_replay = Replay.new()
	_replay.game = Replay.game_of(level)
	_replay.board_id = level.board_id
	_replay.board_hash = Replay.board_hash_of(level)
	_replay.rng_seed = rng_seed
	_replay.step_hz = roundi(1.0 / step_seconds)


func _world() -> BallWorld:
	return _maze.world if _maze != null else _pachinko.world


func _add_frame(steps: int) -> void:
	if _maze != null:
		var tilt := (_maze.tilt * Replay.HUNDREDTHS).round()
		_add_maze_frame(steps, int(tilt.x), int(tilt.y))
		return
	var records := _replay.records
	if not records.is_empty() and records[-1][0] == "run" and records[-1][2] == steps:
		records[-1][1] += 1
		return
	records.append(["run", 1, steps])


# A held tilt grows a "tilt" record; a changing one goes into a "tilts" record, and once the
# tilt has stayed the same for HELD_FRAMES frames they move out into a "tilt" record.
func _add_maze_frame(steps: int, x: int, y: int) -> void:
	var records := _replay.records
	var last: Array = records[-1] if not records.is_empty() else []
	if (
		last.is_empty()
		or last[0] != "tilts"
		or Replay.frame_count(last) >= Replay.MAX_PACKED_FRAMES
	):
		if not last.is_empty() and last[0] == "tilt" and last.slice(2) == [steps, x, y]:
			last[1] += 1
		else:
			records.append(["tilts", steps, x, y])
		return
	last.append_array([steps, x, y])
	var frames := Replay.frame_count(last)
	if frames < HELD_FRAMES:
		return
	var frame := [steps, x, y]
	for back in range(frames - HELD_FRAMES, frames - 1):
		if last.slice(1 + 3 * back, 4 + 3 * back) != frame:
			return
	last.resize(last.size() - 3 * HELD_FRAMES)
	if last.size() == 1:
		records.pop_back()
	records.append(["tilt", HELD_FRAMES, steps, x, y])


func _on_maze_started() -> void:
	_replay.records.clear()
	_too_long = false
	_noted_steps = _maze.world.step_count
	_recording = true


func _on_maze_reset() -> void:
	_replay.records.clear()
	_recording = false


func _on_pachinko_started(_cup: int) -> void:
	note_frame()
	if not _recording:
		return
	_replay.records.append(["start", _pachinko.world.step_count])
	if _pachinko.bonus.has_house_jackpot():  # granted before the game began
		_replay.records.append(["house", _pachinko.world.step_count])


# The house's jackpot granted mid-game (HouseJackpot, after its shots): the step it came at.
func _on_house_granted() -> void:
	if _recording:
		_replay.records.append(["house", _pachinko.world.step_count])


func _on_ball_launched(_ball_id: int, power: float, _speed: float) -> void:
	note_frame()
	if not _recording:
		return
	_replay.records.append(["fire", _pachinko.world.step_count, roundi(power * Replay.HUNDREDTHS)])
