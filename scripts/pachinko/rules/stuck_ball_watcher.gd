class_name StuckBallWatcher
extends RefCounted
## Finds balls resting on pins. The chapter lets balls get stuck so another ball can knock
## them loose; that still works, but a ball that has not moved for `rest_seconds` is handed
## back for a small nudge so a game can always end.

## Seconds between position checks.
const CHECK_INTERVAL := 0.5
## A ball that moved less than this between checks counts as resting, in pixels.
const REST_DISTANCE := 1.5

## Seconds of rest before a nudge.
var rest_seconds := 3.0

var _since_check := 0.0
var _last_pos: Dictionary[int, Vector2] = {}
var _rest_time: Dictionary[int, float] = {}


## Forgets a ball that left play.
func forget(ball_id: int) -> void:
	_last_pos.erase(ball_id)
	_rest_time.erase(ball_id)


## Forgets every ball.
func clear() -> void:
	_last_pos.clear()
	_rest_time.clear()
	_since_check = 0.0


## Advances the watch by `delta` seconds; returns the ids that have rested too long (their
## rest timers restart, so a ball is nudged again only if it stays put).
func update(world: BallWorld, ball_ids: Array, delta: float) -> PackedInt32Array:
	var due := PackedInt32Array()
	_since_check += delta
	if _since_check < CHECK_INTERVAL:
		return due
	var elapsed := _since_check
	_since_check = 0.0
	for id: int in ball_ids:
		if not world.has_ball(id):
			continue
		var pos := world.get_ball_position(id)
		var last: Vector2 = _last_pos.get(id, Vector2.INF)
		_last_pos[id] = pos
		if last != Vector2.INF and pos.distance_to(last) < REST_DISTANCE:
			var rested: float = _rest_time.get(id, 0.0) + elapsed
			if rested >= rest_seconds:
				due.append(id)
				rested = 0.0
			_rest_time[id] = rested
		else:
			_rest_time[id] = 0.0
	return due
