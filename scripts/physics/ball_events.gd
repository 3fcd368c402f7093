class_name BallEvents
extends RefCounted
## The kinds of event a step queues: (kind, ball id, index) triples plus a speed each, in
## the order they happened, which BallWorld then emits as its signals. Internal to
## scripts/physics; it knows no world, so the stages that queue events stay below BallWorld.

enum Kind { PIN_HIT, WALL_HIT, RING_HIT, BLADE_HIT, CAPTURED, DRAINED, HOLE, GOAL, GOAL_LEFT, ZONE }
