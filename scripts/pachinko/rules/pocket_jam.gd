class_name PocketJam
extends RefCounted
## Catches balls jammed inside a pocket's cup. A pocket is a little under two balls wide
## between its rim pins, so two balls that drop in together wedge against the rim above
## the special pin: an arch neither ball can leave. In a real machine the pocket is a hole
## and both would go in, so a ball that stays slow inside a cup for `JAM_SECONDS` is caught
## as if it had reached the special pin.

## Seconds a ball may sit slow inside a cup before it counts as caught.
const JAM_SECONDS := 0.4
## Below this speed (px/s) a ball inside a cup counts as sitting.
const SLOW_SPEED := 25.0

var _slow_time: Dictionary[int, float] = {}


## The pocket whose cup holds a ball centred at `at`: below the mouth by a ball radius and
## between the rim pins. -1 when none does.
static func pocket_at(level: BoardLevel, at: Vector2) -> int:
	for i in level.pockets.size():
		var spec: PocketSpec = level.pockets[i]
		var rel := at - spec.position
		var inner_half := spec.width * 0.5 - level.pin_radius
		if absf(rel.x) < inner_half and rel.y >= level.ball_radius and rel.y <= spec.depth:
			return i
	return -1


## Advances the watch by `delta` seconds over the balls `ball_ids` of `world`. Returns the
## balls caught now, as ball id -> pocket index; they are forgotten here.
func update(level: BoardLevel, world: BallWorld, ball_ids: Array, delta: float) -> Dictionary:
	var caught: Dictionary = {}
	for id: int in ball_ids:
		if not world.has_ball(id):
			continue
		var pocket := pocket_at(level, world.get_ball_position(id))
		if pocket < 0 or world.get_ball_velocity(id).length() >= SLOW_SPEED:
			_slow_time.erase(id)
			continue
		var sat: float = _slow_time.get(id, 0.0) + delta
		if sat >= JAM_SECONDS:
			caught[id] = pocket
			_slow_time.erase(id)
		else:
			_slow_time[id] = sat
	return caught


## Forgets a ball that left play.
func forget(ball_id: int) -> void:
	_slow_time.erase(ball_id)
