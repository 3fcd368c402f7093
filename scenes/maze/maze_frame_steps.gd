class_name MazeFrameSteps
extends RefCounted
## Runs one drawn frame's real time through the maze rules, so the clock (the rules' steps)
## keeps real time on a slow computer: a play trial on software GL saw 20.5 s read 0:14.4 at
## 4-17 FPS, and medals are judged on that clock. The world takes at most
## BallWorld.MAX_STEPS_PER_ADVANCE steps (0.25 s) per advance and drops the rest as a hitch,
## so a slow frame goes in pieces, each noted as a frame of the replay.

## Frames up to this long (seconds; 2 FPS) count whole; a longer one (a window drag, a
## breakpoint) counts this much, as the world drops a hitch's backlog. The project's
## physics/common/max_physics_steps_per_frame lets the engine pass such frames on whole.
const SLOWEST_FRAME := 0.5
## Each piece is this long at most: the world's 30 steps less room for the time it carries.
const PIECE_SECONDS := 0.2


## Runs `delta` seconds (at most SLOWEST_FRAME) of play through `rules`, noting each piece on
## `recorder`; returns the steps run. Does nothing unless playing.
static func run(rules: MazeRules, recorder: ReplayRecorder, delta: float) -> int:
	if not is_finite(delta) or delta <= 0.0:
		return 0
	var left := minf(delta, SLOWEST_FRAME)
	var steps := 0
	while left > 0.0 and rules.is_playing():
		var piece := minf(left, PIECE_SECONDS)
		steps += rules.advance(piece)
		recorder.note_frame()
		left -= piece
	return steps
