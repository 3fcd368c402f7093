class_name WorldSignals
extends RefCounted
## Between a BallWorld step's queued events (BallEvents: kind, ball id, index; and a speed)
## and the world's signals: which hit kinds anyone listens to, and the emitting itself, in
## the order the events happened. Internal to scripts/physics.
##
## The world comes in as an Object and its signals are taken by name (Signal(world, name)):
## naming the BallWorld class here would make the two files need each other.


## Sets `heard[kind]` to 1 for each hit event kind some handler of `world` listens to:
## hits are most of a busy board's events, and one nobody hears need not be queued,
## gathered or emitted.
static func hear_hits(world: Object, heard: PackedByteArray) -> void:
	heard[BallEvents.Kind.PIN_HIT] = 1 if _heard(world, &"pin_hit") else 0
	heard[BallEvents.Kind.WALL_HIT] = 1 if _heard(world, &"wall_hit") else 0
	heard[BallEvents.Kind.RING_HIT] = 1 if _heard(world, &"ring_hit") else 0
	var blades: bool = _heard(world, &"windmill_hit") or _heard(world, &"gate_hit")
	heard[BallEvents.Kind.BLADE_HIT] = 1 if blades else 0


## Emits events `ev` (three ints each) with speeds `evs` as `world`'s signals, in order;
## `shapes` (the world's) says which windmill or gate a blade hit belongs to.
static func emit(
	world: Object, shapes: WorldShapes, ev: PackedInt32Array, evs: PackedFloat32Array
) -> void:
	for e: int in evs.size():
		var kind: int = ev[e * 3]
		var id: int = ev[e * 3 + 1]
		var index: int = ev[e * 3 + 2]
		match kind:
			BallEvents.Kind.PIN_HIT:
				Signal(world, &"pin_hit").emit(id, index, evs[e])
			BallEvents.Kind.WALL_HIT:
				Signal(world, &"wall_hit").emit(id, index, evs[e])
			BallEvents.Kind.RING_HIT:
				Signal(world, &"ring_hit").emit(id, evs[e])
			BallEvents.Kind.BLADE_HIT:
				# A rotor is a windmill or a gate's petal: each signal names its own.
				if shapes.rotor_is_petal(index):
					Signal(world, &"gate_hit").emit(id, shapes.rotor_owner(index), evs[e])
				else:
					Signal(world, &"windmill_hit").emit(id, shapes.rotor_owner(index), evs[e])
			BallEvents.Kind.CAPTURED:
				Signal(world, &"ball_captured").emit(id, index)
			BallEvents.Kind.DRAINED:
				Signal(world, &"ball_drained").emit(id)
			BallEvents.Kind.HOLE:
				Signal(world, &"ball_fell_in_hole").emit(id, index)
			BallEvents.Kind.GOAL:
				Signal(world, &"ball_reached_goal").emit(id, index)
			BallEvents.Kind.GOAL_LEFT:
				Signal(world, &"ball_left_goal").emit(id, index)
			BallEvents.Kind.ZONE:
				Signal(world, &"ball_entered_zone").emit(id, index)


static func _heard(world: Object, signal_name: StringName) -> bool:
	return Signal(world, signal_name).has_connections()
