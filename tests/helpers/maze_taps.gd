extends RefCounted
## Key presses played through the maze game's own path (a TiltMixer hearing the press event,
## then MazeFrameSteps each frame), for the tap tests and their table (trial 9).
## A press lands in the frame that ends after it (its event comes before that frame runs);
## a frame sees the key held when the frame ends while it is down (the game reads the keys
## once a frame), so a press shorter than a frame is held in no frame at all.

## The board the taps are measured on: Switchbacks (35 px corridor cells, 25 px wide).
const BOARD := "res://levels/maze/switchbacks.board"
## Its first ball, pressed right: it has the corridor's length to roll.
const KEY := Vector2.RIGHT
## How long a run lasts (seconds): long enough for a nudged ball to stop.
const RUN_SECONDS := 4.0


## Plays `board` with frames of 1 / `fps` s: `key` is pressed at each of `presses` (seconds)
## and held `seconds` each time. Returns ball `ball`'s travel along `key` (px).
## `jitter` > 0: each frame lasts 1 / `fps` s times 1 ± jitter, drawn from `rng` (a busy
## machine's uneven frames). `fine`: the fine key held throughout.
static func travel(
	seconds: float,
	fps: float,
	presses: Array[float] = [0.0],
	fine := false,
	jitter := 0.0,
	rng: RandomNumberGenerator = null,
	board := BOARD,
	ball := 0,
	key := KEY
) -> float:
	var rules := MazeRules.new(BoardLoader.load_board(board).level)
	var mixer := TiltMixer.new()
	var recorder := ReplayRecorder.new()
	recorder.attach_maze(rules)
	var before := rules.ball_positions()[ball]
	rules.start()
	var ends := 0.0
	var next := 0
	while ends < RUN_SECONDS:
		var frame := 1.0 / fps
		if jitter > 0.0:
			frame *= rng.randf_range(1.0 - jitter, 1.0 + jitter)
		ends += frame
		while next < presses.size() and presses[next] < ends - 0.0001:
			mixer.key_pressed(key)
			next += 1
		var keys := Vector2.ZERO
		for at in presses:
			if ends > at and ends <= at + seconds + 0.0001:
				keys = key
		MazeFrameSteps.run(rules, recorder, frame, mixer, keys, Vector3.ZERO, fine)
	return (rules.ball_positions()[ball] - before).dot(key)
