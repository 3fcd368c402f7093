extends RefCounted
## The events of a step: queued as (kind, ball id, index) triples plus a speed each, in the
## order they happened, then emitted as BallWorld's signals. Internal to scripts/physics.

enum Kind { PIN_HIT, WALL_HIT, RING_HIT, BLADE_HIT, CAPTURED, DRAINED, HOLE, GOAL, GOAL_LEFT, ZONE }


## Emits every queued event on `world`.
static func emit_all(world: BallWorld, ev: PackedInt32Array, evs: PackedFloat32Array) -> void:
	for e: int in evs.size():
		var kind: int = ev[e * 3]
		var id: int = ev[e * 3 + 1]
		var index: int = ev[e * 3 + 2]
		match kind:
			Kind.PIN_HIT:
				world.pin_hit.emit(id, index, evs[e])
			Kind.WALL_HIT:
				world.wall_hit.emit(id, index, evs[e])
			Kind.RING_HIT:
				world.ring_hit.emit(id, evs[e])
			Kind.BLADE_HIT:
				world.windmill_hit.emit(id, index, evs[e])
			Kind.CAPTURED:
				world.ball_captured.emit(id, index)
				if world.ball_pocketed.has_connections():
					world.ball_pocketed.emit(id, index)
			Kind.DRAINED:
				world.ball_drained.emit(id)
			Kind.HOLE:
				world.ball_fell_in_hole.emit(id, index)
			Kind.GOAL:
				world.ball_reached_goal.emit(id, index)
			Kind.GOAL_LEFT:
				world.ball_left_goal.emit(id, index)
			Kind.ZONE:
				world.ball_entered_zone.emit(id, index)
