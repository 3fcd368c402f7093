extends RefCounted
## Between a BallWorld step's queued events (BallEvents: kind, ball id, index; and a speed)
## and the world's signals: which hit kinds anyone listens to, and the emitting itself, in
## the order the events happened. Internal to scripts/physics.

const BallEvents := preload("res://scripts/physics/ball_events.gd")


## Sets `heard[kind]` to 1 for each hit event kind some handler of `world` listens to:
## hits are most of a busy board's events, and one nobody hears need not be queued,
## gathered or emitted.
static func hear_hits(world: BallWorld, heard: PackedByteArray) -> void:
	heard[BallEvents.Kind.PIN_HIT] = 1 if world.pin_hit.has_connections() else 0
	heard[BallEvents.Kind.WALL_HIT] = 1 if world.wall_hit.has_connections() else 0
	heard[BallEvents.Kind.RING_HIT] = 1 if world.ring_hit.has_connections() else 0
	var blades: bool = world.windmill_hit.has_connections() or world.gate_hit.has_connections()
	heard[BallEvents.Kind.BLADE_HIT] = 1 if blades else 0


## Emits events `ev` (three ints each) with speeds `evs` as `world`'s signals, in order.
static func emit(world: BallWorld, ev: PackedInt32Array, evs: PackedFloat32Array) -> void:
	for e: int in evs.size():
		var kind: int = ev[e * 3]
		var id: int = ev[e * 3 + 1]
		var index: int = ev[e * 3 + 2]
		match kind:
			BallEvents.Kind.PIN_HIT:
				world.pin_hit.emit(id, index, evs[e])
			BallEvents.Kind.WALL_HIT:
				world.wall_hit.emit(id, index, evs[e])
			BallEvents.Kind.RING_HIT:
				world.ring_hit.emit(id, evs[e])
			BallEvents.Kind.BLADE_HIT:
				# A rotor is a windmill or a gate's petal: each signal names its own.
				if world.shapes.rotor_is_petal(index):
					world.gate_hit.emit(id, world.shapes.rotor_owner(index), evs[e])
				else:
					world.windmill_hit.emit(id, world.shapes.rotor_owner(index), evs[e])
			BallEvents.Kind.CAPTURED:
				world.ball_captured.emit(id, index)
			BallEvents.Kind.DRAINED:
				world.ball_drained.emit(id)
			BallEvents.Kind.HOLE:
				world.ball_fell_in_hole.emit(id, index)
			BallEvents.Kind.GOAL:
				world.ball_reached_goal.emit(id, index)
			BallEvents.Kind.GOAL_LEFT:
				world.ball_left_goal.emit(id, index)
			BallEvents.Kind.ZONE:
				world.ball_entered_zone.emit(id, index)
