class_name Replay
extends RefCounted
## One recorded game as plain data: which board (its id and a hash of its content), the
## seed, the mode, and the inputs as a list of records, plus the step count and the world's
## state hash at the end. Playing the records through the same rules on the same board must
## end in the same state hash (ReplayPlayer). Read and written as JSON Lines by
## ReplayReader / ReplayWriter; the format is described in scripts/replay/README.md.
##
## A record is an Array whose first item names it; the rest are whole numbers:
## [br]- `["tilt", frames, steps, x, y]`: maze, `frames` frames in a row, each running `steps`
##   fixed steps with the tilt (x, y) in hundredths of a degree (run-length encoded: a held tilt).
## [br]- `["tilts", steps, x, y, steps, x, y, ...]`: maze, up to MAX_PACKED_FRAMES frames whose
##   tilt changes every frame, each with its own steps and tilt (format 2). The file packs
##   them into one short text (tilt_packing.gd): `["tilts", "BAA..."]`.
## [br]- `["run", frames, steps]`: pachinko, `frames` frames of `steps` steps each.
## [br]- `["start", step]`: pachinko, a game started (the cup was filled) before `step`.
## [br]- `["fire", step, power]`: pachinko, a shot with power in hundredths (0..10000).
## [br]- `["house", step]`: pachinko, the game's next spin is the house's jackpot (a new
## player's first, BonusMachine.grant_house_jackpot).
## Events carry the world's step count when they happened, a check the reader makes.

## The format this build writes; it reads this one and every older one (format 1 has no
## `"tilts"` records; formats 1 and 2 have no `"physics"`, their runs are physics 1;
## formats 1 to 3 have no `"rules"`, their runs are rules 1).
const VERSION := 4
## The physics behaviour this build plays runs with (BallWorld.PHYSICS_VERSION). A run
## recorded under another one cannot be replayed exactly: the same inputs roll the balls
## differently, so the replay and its ghost are refused, by name, instead of drifting.
const PHYSICS_VERSION := BallWorld.PHYSICS_VERSION
## Per game, the version of its rules this build plays. The same inputs on the same
## physics play out differently under other rules, so those runs are refused too.
## Pachinko 2: every power clears the rail and power sets the speed at the rail's mouth
## (LaunchTable), so a recorded shot's power sends its ball elsewhere than under 1.
## Pachinko 3: a tulip's wings are moving petals (a world gate) instead of walls switched
## in one step, so a run on a board with tulips rolls differently than under 2.
## Pachinko 4: a jackpot is ten rounds (JackpotRounds), a reach's last reel turns longer and
## the first spin no longer waits, so a run on a board with reels plays differently than
## under 3.
## Pachinko 5: the handle's spring spreads its balls over 6 points of strength either side
## (LaunchHandle.JITTER, 2 before), so a recorded handle stream plays differently than
## under 4, and the shipped boards' payouts were re-tuned so the best held strength pays far
## less than before (tools/power_returns.gd; still more than it costs on every board).
## Pachinko 6: Fever's and Hanami's attackers moved off the middle to the far side, fed
## best at handle strengths 75 to 85 (AttackerBands), Fever's left plain pocket gave way to
## it and the catches pay more; and a new player's first start-pocket hit on a reel machine
## lands a jackpot (the "house" record); so a run on those boards plays differently than
## under 5.
## Pachinko 8 (trial 8): Fever's and Hanami's reels turn 5 symbols (one jackpot in 25 spins,
## not 81) and their attackers pay 4 and 3 a catch (17 and 20): smaller jackpots, more
## often; and a jackpot within 15 s of the last one's end opens its round 1 only after a
## 5 s announcement (JackpotRounds.AGAIN_SECONDS), so a run there plays differently.
## Pachinko 9: gold pins (GoldPins): a lit one a ball touches adds a ball to the cup, and a
## cleared set brings a Gold spin or a Gold rush (double pay), so the cup runs differently.
## Maze 2: the goal is a dish that holds the balls that roll in (GoalDip).
## Maze 3: the dish wakes only the balls it holds (it woke every ball each step), so balls
## resting elsewhere fall asleep while one sits in the dish and a run plays differently.
## Maze 4: a ball is in the goal once its drawn disc overlaps the dish's rim (its centre
## within the rim plus a ball's radius): it counts there and the dish pulls it in from there,
## so a ball grazing the rim is caught and a run can be won a little sooner.
const RULES_VERSIONS := {"maze": 5, "pachinko": 9}
## Frames one `"tilts"` record holds at most (a line of about a kilobyte).
const MAX_PACKED_FRAMES := 250
const MAZE := BoardLevel.MAZE_NAME
const PACHINKO := BoardLevel.PACHINKO_NAME
## Pachinko has one mode; the maze has easy and hard.
const PACHINKO_MODE := "normal"
## Record kinds and how many numbers follow the name, per game.
const RECORD_SIZES := {
	MAZE: {"tilt": 4, "tilts": 1},
	PACHINKO: {"run": 2, "start": 1, "fire": 2, "house": 1},
}
## Tilt and power are kept in hundredths by the rules (MazeRules, PachinkoRules).
const HUNDREDTHS := 100.0

## The format version of the file it was read from (VERSION when made by this build).
var format_version := VERSION
## The physics behaviour the run was recorded with (PHYSICS_VERSION when recorded here).
var physics_version := PHYSICS_VERSION
## The game's rules version the run was recorded with (RULES_VERSIONS when recorded here).
var rules_version := 1
## The game's name (BoardLevel.KIND_NAMES).
var game := MAZE
## The board's `board_id`.
var board_id := ""
## SHA-256 of the board's canonical text without its naming lines (`board_hash_of`): the
## board played must play as this one. Replays recorded before held the whole text's hash
## (`content_hash`), which `recorded_on` still accepts.
var board_hash := ""
## The seed the rules were built with (pachinko nudges; the maze autoplay's pilot).
var rng_seed := 0
## Maze: black holes live. Pachinko: always false.
var hard := false
## The world's fixed steps per second when recorded.
var step_hz := 120
## Fixed steps the world ran in the whole recording.
var steps := 0
## `BallWorld.state_hash()` at the end of the recording.
var state_hash := 0
## Seconds on the game's clock at the end (the maze's run time), for showing only.
var seconds := 0.0
## The records, in order (see the class notes).
var records: Array[Array] = []


## The mode's name as the file writes it: "easy" or "hard" for the maze, "normal" for pachinko.
func mode_name() -> String:
	if game == PACHINKO:
		return PACHINKO_MODE
	return "hard" if hard else "easy"


## The content hash of a board (BoardTextWriter.content_hash).
static func content_hash(level: BoardLevel) -> String:
	return BoardTextWriter.content_hash(level)


## The hash a new replay keeps of its board: the play hash (BoardTextWriter.play_hash), which
## leaves out the board's name, description, look and medal times. A ghost then survives
## new medal times (a player's saved ghosts were lost each time they were re-measured);
## any change to how the board plays still refuses the replay.
static func board_hash_of(level: BoardLevel) -> String:
	return BoardTextWriter.play_hash(level)


## Whether this replay was recorded on a board that plays as `level` does: its hash is the
## board's play hash, or (a replay recorded before play hashes) its whole content hash.
func recorded_on(level: BoardLevel) -> bool:
	return board_hash == board_hash_of(level) or board_hash == content_hash(level)


## How many frames a `"tilt"`, `"tilts"` or `"run"` record plays (0 for an event).
static func frame_count(record: Array) -> int:
	match record[0]:
		"tilt", "run":
			return record[1]
		"tilts":
			@warning_ignore("integer_division")
			return (record.size() - 1) / 3
	return 0


## The fixed steps of frame `frame` of a `"tilt"`, `"tilts"` or `"run"` record.
static func frame_steps(record: Array, frame: int) -> int:
	return record[1 + 3 * frame] if record[0] == "tilts" else record[2]


## The tilt in hundredths of a degree of frame `frame` of a maze record.
static func frame_tilt(record: Array, frame: int) -> Vector2i:
	var at := 2 + 3 * frame if record[0] == "tilts" else 3
	var x: int = record[at]
	var y: int = record[at + 1]
	return Vector2i(x, y)


## The game's name for a board (BoardLevel.KIND_NAMES).
static func game_of(level: BoardLevel) -> String:
	return BoardLevel.kind_name(level.kind)


## The rules version this build plays `game_name` with.
static func rules_version_of(game_name: String) -> int:
	return RULES_VERSIONS.get(game_name, 1)


## Why this build cannot replay the run exactly (another physics or rules version), or ""
## when it can.
func physics_problem() -> String:
	if physics_version == PHYSICS_VERSION:
		return rules_problem()
	return (
		(
			"it was recorded with physics version %d and this game runs version %d, which rolls "
			+ "the balls differently"
		)
		% [physics_version, PHYSICS_VERSION]
	)


## Why this build's rules cannot replay the run exactly, or "" when they can.
func rules_problem() -> String:
	var current := rules_version_of(game)
	if rules_version == current:
		return ""
	return (
		(
			"it was recorded with %s rules version %d and this game plays version %d, where a shot "
			% [game, rules_version, current]
		)
		+ "of the same strength goes elsewhere"
	)
