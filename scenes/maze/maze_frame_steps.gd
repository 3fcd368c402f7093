class_name MazeFrameSteps
extends RefCounted
## Runs one drawn frame's real time through the maze rules, so the clock (the rules' steps)
## and the tilt keep real time on a slow computer: a play trial on software GL saw 20.5 s
## read 0:14.4 at 4-17 FPS, and medals are judged on that clock; a later one at 2-6 FPS
## still saw the clock run slow (frames over 0.5 s were cut) and the board answer the keys
## differently. The world takes at most BallWorld.MAX_STEPS_PER_ADVANCE steps (0.25 s) per
## advance and drops the rest as a hitch, so a slow frame goes in pieces, each noted as a
## frame of the replay; with the player's controls, a piece is one physics step, each with
## its own tilt.

## Frames up to this long (seconds; half a frame a second) count whole; a longer one (a
## window drag, a breakpoint) counts this much, as the world drops a hitch's backlog. The
## cap is what keeps a slow computer out of a spiral: a frame never owes more than 240
## steps of four balls (a few milliseconds). The project's
## physics/common/max_physics_steps_per_frame lets the engine pass such frames on whole.
const SLOWEST_FRAME := 2.0
## Each piece is this long at most: the world's 30 steps less room for the time it carries.
const PIECE_SECONDS := 0.2


## Runs `delta` seconds (at most SLOWEST_FRAME) of play through `rules`, noting each piece on
## `recorder`; returns the steps run. Does nothing unless playing. With a `mixer`, the tilt
## moves step by step: before each physics step the mixer runs that step's time from the
## `keys`, `accel` and `fine` readings, and each step is noted with the tilt it ran with, so
## a frame of 0.1 s tilts the board as six frames of 1/60 s do (trial 8: taps of one length
## moved a ball anywhere from 8 to 130 px at 3 to 39 FPS).
static func run(
	rules: MazeRules,
	recorder: ReplayRecorder,
	delta: float,
	mixer: TiltMixer = null,
	keys := Vector2.ZERO,
	accel := Vector3.ZERO,
	fine := false
) -> int:
	if not is_finite(delta) or delta <= 0.0:
		return 0
	var left := minf(delta, SLOWEST_FRAME)
	# a piece of one step's length runs exactly one step (the world keeps less than a step)
	var piece_most := rules.step_seconds() if mixer != null else PIECE_SECONDS
	var steps := 0
	while left > 0.0 and rules.is_playing():
		var piece := minf(left, piece_most)
		if mixer != null:
			rules.set_tilt(mixer.update(piece, keys, accel, fine))
		var ran := rules.advance(piece)
		steps += ran
		if ran > 0 or mixer == null:
			recorder.note_frame()
		left -= piece
	return steps


## One drawn frame of the maze screen: while playing, `delta` runs through `run` with the keys
## (`keys`, the fine key read here) and `accel`; once the run is over the board eases back to
## level as a key let go would, won or lost (trial 9: after a ball was lost the board stayed
## drawn tilted, "which looks like a freeze"), and a won board's dip gathers the balls in.
static func play_frame(
	rules: MazeRules,
	recorder: ReplayRecorder,
	delta: float,
	mixer: TiltMixer,
	keys: Vector2,
	accel: Vector3
) -> void:
	if rules.is_playing():
		run(rules, recorder, delta, mixer, keys, accel, Input.is_action_pressed("tilt_fine"))
	elif rules.is_over():
		rules.set_tilt(KeyTilt.level_toward(rules.tilt, delta))
		if rules.state == MazeRules.State.WON:
			rules.settle(minf(delta, PIECE_SECONDS))
