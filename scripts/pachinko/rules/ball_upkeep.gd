class_name BallUpkeep
extends RefCounted
## Keeps the balls in play moving toward an end, between steps: finds a ball the world
## dropped without a signal, a ball wedged in a pocket's cup (PocketJam) and a ball
## resting on pins (StuckWatcher), and gives a resting ball a small push. It decides
## nothing about the game: PachinkoRules counts and pays what it reports.

## Speed of the nudge given to a resting ball, px/s.
const NUDGE_SPEED := 70.0

var _watcher := StuckBallWatcher.new()
var _jam := PocketJam.new()


## The balls of `in_play` that `world` no longer holds.
static func vanished(world: BallWorld, in_play: Array) -> PackedInt32Array:
	var gone := PackedInt32Array()
	if world.ball_count() == in_play.size():
		return gone
	for id: int in in_play:
		if not world.has_ball(id):
			gone.append(id)
	return gone


## The balls of `in_play` that sat wedged in a pocket's cup long enough to count as
## caught, as ball id -> pocket index, after `seconds` more of play.
func jammed(level: BoardLevel, world: BallWorld, in_play: Array, seconds: float) -> Dictionary:
	return _jam.update(level, world, in_play, seconds)


## Pushes every ball of `in_play` that has rested too long (after `seconds` more of play)
## up and to a side drawn from `rng`; returns their ids.
func nudge_resting(
	world: BallWorld, in_play: Array, seconds: float, rng: RandomNumberGenerator
) -> PackedInt32Array:
	var due := _watcher.update(world, in_play, seconds)
	for id in due:
		var side := -1.0 if rng.randf() < 0.5 else 1.0
		var push := Vector2(side * rng.randf_range(0.5, 1.0), -0.6).normalized() * NUDGE_SPEED
		world.set_ball_velocity(id, world.get_ball_velocity(id) + push)
	return due


## Forgets a ball that left play.
func forget(ball_id: int) -> void:
	_watcher.forget(ball_id)
	_jam.forget(ball_id)
