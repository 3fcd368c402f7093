class_name BallSleep
extends RefCounted
## The sleepers' part of a BallWorld step: each sleeping ball either stays put or wakes and
## moves with the awake balls in that same step. Internal to scripts/physics; the motion
## stage runs it on each lane's balls just before moving them (the mover skips every ball
## still asleep). Each sleeper reads and writes only its own slots, so lanes may run it
## side by side.
##
## A sleeper keeps the normals of what held it as it fell asleep (BallStore.support_static,
## support_static2, sleep_ball_normal). When gravity or friction changed, it stays asleep
## only while those shapes take every part of the new gravity that presses into them and
## rolling friction holds the rest. One held up by balls also wakes the step it touches
## no ball: the ball under it was knocked away.
##
## One loop with the test inline, not a call per sleeper: a GDScript call costs about as
## much as the test, and a tilting maze runs it for hundreds of sleepers every step.

## Share of gravity that rounding in a contact normal may leave unbalanced.
const HELD_SLACK := 1e-3


## Ball `i`, which has just rested (moved slower than the rest speed) for the tuning's
## sleep time, falls asleep unless it is still being pushed apart (by `settled_push` px or
## more: still settling) or lies on the drain arc (it must still drain). Called by the
## motion lanes, each for its own balls (the mover adds up the rest time itself, in its
## members: most resting balls are not due yet, and a read of the store by name costs a
## lookup).
static func sleep_if_settled(b: BallStore, i: int, settled_push: float) -> void:
	var push: Vector2 = b.push[i]
	if push.length() >= settled_push or b.drain_time[i] != 0.0 or b.drain_hits[i] != 0:
		return
	var on_ball: Vector2 = b.support_ball[i]
	b.asleep[i] = BallStore.SLEEP_HELD if on_ball == Vector2.ZERO else BallStore.SLEEP_ON_BALLS
	b.sleep_ball_normal[i] = on_ball
	b.vel[i] = Vector2.ZERO


## Settles the sleepers in slots from..to for one step of `dt` s under `gravity` with
## per-axis rolling `friction` (px/s²; below zero counts as zero, as in the motion stage).
## `turned` says gravity or friction changed since the last step. A sleeper that stays gets
## its velocity zeroed (the gravity phase added this step's pull) and `dt` more rest; one
## that wakes keeps its velocity and moves this step.
static func settle(
	b: BallStore, from: int, to: int, gravity: Vector2, friction: Vector2, dt: float, turned: bool
) -> void:
	var asleep: PackedByteArray = b.asleep
	var vel: PackedVector2Array = b.vel
	var rest: PackedFloat32Array = b.rest
	var touching: PackedByteArray = b.touching
	var sup_a: PackedVector2Array = b.support_static
	var sup_b: PackedVector2Array = b.support_static2
	var on_ball: PackedVector2Array = b.sleep_ball_normal
	# Rounding in the normals must not wake a ball lying exactly on its support.
	var slack: float = HELD_SLACK * gravity.length()
	var fx: float = maxf(friction.x, 0.0) + slack
	var fy: float = maxf(friction.y, 0.0) + slack
	for i: int in range(from, to):
		var kind: int = asleep[i]
		if kind == 0:
			continue
		var stays: bool = kind == BallStore.SLEEP_HELD or touching[i] != 0
		if stays and turned:
			var na: Vector2 = sup_a[i]
			var nb: Vector2 = sup_b[i]
			if kind == BallStore.SLEEP_ON_BALLS and nb == Vector2.ZERO:
				# Against the ball it rests on, and its wall if it has one.
				nb = on_ball[i]
			# What presses into a face is taken by it; sliding along one face is free
			# only if it does not run into the other. Friction must hold what is left.
			var left: Vector2 = gravity
			var da: float = gravity.dot(na)
			var db: float = gravity.dot(nb)
			if da < 0.0 or db < 0.0:
				var along_a: Vector2 = gravity - na * da
				left = Vector2.ZERO
				if da < 0.0 and along_a.dot(nb) >= 0.0:
					left = along_a
				elif db < 0.0:
					var along_b: Vector2 = gravity - nb * db
					if along_b.dot(na) >= 0.0:
						left = along_b
			stays = absf(left.x) <= fx and absf(left.y) <= fy
		if stays:
			vel[i] = Vector2.ZERO
			rest[i] += dt
		else:
			asleep[i] = 0
			rest[i] = 0.0
