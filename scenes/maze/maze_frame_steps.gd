class_name MazeFrameSteps
extends RefCounted
## Runs one drawn frame's real time through the maze rules, so the clock (the rules' steps)
## and the tilt keep real time on a slow computer: a play trial on software GL saw 20.5 s
## read 0:14.4 at 4-17 FPS, and medals are judged on that clock; a later one at 2-6 FPS
## still saw the clock run slow (frames over 0.5 s were cut) and the board answer the keys
## differently. The world takes at most BallWorld.MAX_STEPS_PER_ADVANCE steps (0.25 s) per
## advance and drops the rest as a hitch, so a slow frame goes in pieces, each with its own
## tilt (the keys ease the board a piece at a time, as they would frame by frame) and each
## noted as a frame of the replay.

## Frames up to this long (seconds; half a frame a second) count whole; a longer one (a
## window drag, a breakpoint) counts this much, as the world drops a hitch's backlog. The
## cap is what keeps a slow computer out of a spiral: a frame never owes more than 240
## steps of four balls (a few milliseconds). The project's
## physics/common/max_physics_steps_per_frame lets the engine pass such frames on whole.
const SLOWEST_FRAME := 2.0
## Each piece is this long at most: the world's 30 steps less room for the time it carries.
const PIECE_SECONDS := 0.2


## Runs `delta` seconds (at most SLOWEST_FRAME) of play through `rules`, noting each piece on
## `recorder`; returns the steps run. Does nothing unless playing. With a `mixer`, each piece
## first eases the tilt by the piece's length from the `keys` and `accel` readings.
static func run(
	rules: MazeRules,
	recorder: ReplayRecorder,
	delta: float,
	mixer: TiltMixer = null,
	keys := Vector2.ZERO,
	accel := Vector3.ZERO
) -> int:
	if not is_finite(delta) or delta <= 0.0:
		return 0
	var left := minf(delta, SLOWEST_FRAME)
	var steps := 0
	while left > 0.0 and rules.is_playing():
		var piece := minf(left, PIECE_SECONDS)
		if mixer != null:
			rules.set_tilt(mixer.update(piece, keys, accel))
		steps += rules.advance(piece)
		recorder.note_frame()
		left -= piece
	return steps
