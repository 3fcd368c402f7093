extends RefCounted
## Turns a step's queued (kind, ball id, index) triples and speeds into BallWorld's signals,
## in the order they happened. Internal to scripts/physics.

const BallStep := preload("res://scripts/physics/ball_step.gd")


## Emits every queued event on `world`.
static func emit_all(world: BallWorld, ev: PackedInt32Array, evs: PackedFloat32Array) -> void:
	for e: int in evs.size():
		var kind: int = ev[e * 3]
		var id: int = ev[e * 3 + 1]
		var index: int = ev[e * 3 + 2]
		match kind:
			BallStep.Ev.PIN_HIT:
				world.pin_hit.emit(id, index, evs[e])
			BallStep.Ev.WALL_HIT:
				world.wall_hit.emit(id, index, evs[e])
			BallStep.Ev.RING_HIT:
				world.ring_hit.emit(id, evs[e])
			BallStep.Ev.POCKETED:
				world.ball_pocketed.emit(id, index)
			BallStep.Ev.DRAINED:
				world.ball_drained.emit(id)
			BallStep.Ev.HOLE:
				world.ball_fell_in_hole.emit(id, index)
			BallStep.Ev.GOAL:
				world.ball_reached_goal.emit(id, index)
			BallStep.Ev.GOAL_LEFT:
				world.ball_left_goal.emit(id, index)
			BallStep.Ev.ZONE:
				world.ball_entered_zone.emit(id, index)
