extends RefCounted
## Whether a sleeping ball stays asleep when gravity or friction changes (every step of a
## tilting maze). Internal to scripts/physics; BallMotion asks it once per sleeper per step
## in which gravity turned.
##
## A sleeper keeps the normals of what held it as it fell asleep (BallStore.support_static,
## support_static2, sleep_ball_normal). It stays asleep while those shapes can take every
## part of the new gravity that presses into them and rolling friction can hold the rest.

const BallStore := preload("res://scripts/physics/ball_store.gd")

## Share of gravity that rounding in a contact normal may leave unbalanced.
const HELD_SLACK := 1e-3


## Whether sleeper `i` of kind `kind` (BallStore.SLEEP_*) stays asleep under `gravity`
## with per-axis rolling `friction` (both px/s²). A SLEEP_ON_BALLS sleeper must also still
## touch a ball; BallMotion checks that every step, before asking this.
static func stays_asleep(
	b: BallStore, i: int, kind: int, gravity: Vector2, friction: Vector2
) -> bool:
	var na: Vector2 = b.support_static[i]
	var nb: Vector2 = b.support_static2[i]
	if kind == BallStore.SLEEP_ON_BALLS and nb == Vector2.ZERO:
		# Against the ball it rests on and its wall if it has one (with two walls, those).
		# A ball under it that leaves wakes it the step they part (BallMotion's touch test).
		nb = b.sleep_ball_normal[i]
	return held_still(gravity, friction, na, nb)


## Whether a ball resting on static shapes with normals `na` and `nb` (zero for none) stays
## at rest under `gravity` with per-axis rolling friction `friction` (both px/s²): the
## shapes take every part of gravity that presses into them, and friction must hold what
## is left. The rest is gravity projected onto the directions the shapes leave free.
static func held_still(gravity: Vector2, friction: Vector2, na: Vector2, nb: Vector2) -> bool:
	var da: float = gravity.dot(na)
	var db: float = gravity.dot(nb)
	var left: Vector2 = gravity
	if da < 0.0 or db < 0.0:
		# Sliding along one face is free only if it does not run into the other face.
		var along_a: Vector2 = gravity - na * da
		var along_b: Vector2 = gravity - nb * db
		if da < 0.0 and along_a.dot(nb) >= 0.0:
			left = along_a
		elif db < 0.0 and along_b.dot(na) >= 0.0:
			left = along_b
		else:
			left = Vector2.ZERO
	# Rounding in the normals must not wake a ball lying exactly on its support.
	var slack: float = HELD_SLACK * gravity.length()
	return absf(left.x) <= friction.x + slack and absf(left.y) <= friction.y + slack
