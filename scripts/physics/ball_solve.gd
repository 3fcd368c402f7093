class_name BallSolve
extends RefCounted
## The ball–ball solve: answers touching pairs between equal masses, with velocity
## impulses now and separation as a displacement (`push`) that the motion stage sweeps with
## the ball's own travel. Internal to scripts/physics; BallPairs owns one and hands it the
## pairs of one stripe of cell rows at a time.
##
## Within a list the order matters (a ball's new velocity feeds its next pair), so each list
## is answered in order on one thread. Lists of stripes that share no ball may be answered
## side by side: the solve writes only the two balls of each pair, and reads only them.

## A support counts when its normal is within about 60° of the line between two balls.
const SUPPORT_COS := 0.5
## Share of a ball-ball overlap each ball moves apart per step.
const PUSH_SHARE := 0.4
## Overlap (px) two balls keep rather than being pushed apart: a resting pair stays in
## touch, so each step's contact takes gravity's approach away. Pushed fully apart, it
## would fall back in every step and never settle.
const CONTACT_SLOP := 0.05
## Distances below this count as zero (px).
const EPS := 1e-6

# The step's view of the balls (the BallFields.TABLE rows declared as `_name`) and its
# constants (set by begin()).
var _pos := PackedVector2Array()
var _radius := PackedFloat32Array()
var _vel := PackedVector2Array()
var _push := PackedVector2Array()
var _touching := PackedByteArray()
var _asleep := PackedByteArray()
var _rest := PackedFloat32Array()
var _support_static := PackedVector2Array()
var _support_static2 := PackedVector2Array()
var _support_ball := PackedVector2Array()
var _sup_next := PackedVector2Array()
var _restitution := 0.0
var _threshold := 0.0
var _wake_speed := 0.0
var _gravity_dt := Vector2.ZERO


## Takes this step's balls and constants, and clears last step's pushes and touches. A
## sleeping ball acts as a fixed ball unless hit faster than `wake_speed`, which wakes it;
## contacts slower than `threshold` do not bounce. Against a held ball, the approach this
## step's gravity (`gravity_dt`) gave does not count toward the threshold, as on a static
## shape: otherwise a ball lying on a held ball would bounce on it for ever. Runs on the
## world's thread before any list is answered.
func begin(
	b: BallStore, restitution: float, threshold: float, wake_speed: float, gravity_dt: Vector2
) -> void:
	var n: int = b.ids.size()
	# The lists may be answered on several threads: every array they write needs a buffer
	# of its own first (see BallStore.own_buffers()).
	b.own_buffers()
	b.push.fill(Vector2.ZERO)
	b.touching.resize(n)
	b.touching.fill(0)
	_sup_next = PackedVector2Array()
	_sup_next.resize(n)
	_take_balls(b)
	_restitution = restitution
	_threshold = threshold
	_wake_speed = wake_speed
	_gravity_dt = gravity_dt


# BallFields.take(b, self) written out, as in BallMover._take_balls() (pinned to it by
# tests/unit/test_ball_fields.gd).
func _take_balls(b: BallStore) -> void:
	_pos = b.pos
	_radius = b.radius
	_vel = b.vel
	_push = b.push
	_touching = b.touching
	_asleep = b.asleep
	_rest = b.rest
	_support_static = b.support_static
	_support_static2 = b.support_static2
	_support_ball = b.support_ball


## Hands the supports found this step to the store (each ball's ball support next step).
func finish(b: BallStore) -> void:
	b.support_ball = _sup_next


## Answers the touching pairs (i, j) of one stripe's list (its first `used` entries) in
## order. Each pair is written out in the loop (a call per pair costs about as much as the
## work, and calls do not run side by side on threads), and skipped when both balls sleep.
func solve_pairs(pairs: PackedInt32Array, used: int) -> void:
	for m: int in range(0, used, 2):
		var i: int = pairs[m]
		var j: int = pairs[m + 1]
		_touching[i] = 1
		_touching[j] = 1
		if _asleep[i] != 0 and _asleep[j] != 0:
			continue
		var d: Vector2 = _pos[j] - _pos[i]
		var dist: float = sqrt(d.length_squared())
		var nrm := Vector2(1.0, 0.0)
		if dist > EPS:
			nrm = d / dist
		var sleep_i: bool = _asleep[i] != 0
		var sleep_j: bool = _asleep[j] != 0
		# A real hit wakes the sleeper, which then answers as a free ball. A sleeper's velocity
		# holds just this step's gravity, which the other ball got too: a ball merely pressing
		# on it under gravity does not count as a hit.
		if (sleep_i or sleep_j) and (_vel[i] - _vel[j]).dot(nrm) > _wake_speed:
			var woken: int = i if sleep_i else j
			_asleep[woken] = 0
			_rest[woken] = 0.0
			sleep_i = _asleep[i] != 0
			sleep_j = _asleep[j] != 0
		var vi: Vector2 = Vector2.ZERO if sleep_i else _vel[i]
		var vj: Vector2 = Vector2.ZERO if sleep_j else _vel[j]
		# A ball held from behind (asleep, or pressed last step on a static shape or a held
		# ball that faces the other ball) does not give way: the other takes the whole response.
		var fixed_i: bool = (
			sleep_i
			or _support_static[i].dot(nrm) > SUPPORT_COS
			or _support_static2[i].dot(nrm) > SUPPORT_COS
			or _support_ball[i].dot(nrm) > SUPPORT_COS
		)
		var fixed_j: bool = (
			sleep_j
			or _support_static[j].dot(nrm) < -SUPPORT_COS
			or _support_static2[j].dot(nrm) < -SUPPORT_COS
			or _support_ball[j].dot(nrm) < -SUPPORT_COS
		)
		var s: Vector2 = (
			nrm * (maxf(_radius[i] + _radius[j] - dist - CONTACT_SLOP, 0.0) * PUSH_SHARE)
		)
		if fixed_i != fixed_j:
			# One ball is held from behind: the other takes the whole response, along `away`
			# (from the held ball to it); the support cancels the held ball's own motion into
			# it, so only the free ball's speed counts. Written out, not called: a pile has
			# hundreds of these pairs a step (off_held() is the rule it copies, and
			# tests/unit/test_held_ball_copy.gd pins the two together bit for bit).
			var free: int = i if fixed_j else j
			var away: Vector2 = -nrm if fixed_j else nrm
			var v: Vector2 = vi if fixed_j else vj
			var vn_free: float = v.dot(away)
			if vn_free < 0.0:
				var gn: float = _gravity_dt.dot(away)
				var e_free: float = (
					_restitution if ContactRule.bounces(vn_free, gn, _threshold) else 0.0
				)
				_vel[free] = v - away * ((1.0 + e_free) * vn_free)
			if fixed_j:
				_push[i] -= s * 2.0
			else:
				_push[j] += s * 2.0
			_sup_next[free] = away
		elif not (sleep_i or sleep_j):
			var vn: float = (vj - vi).dot(nrm)
			if vn < 0.0:
				# Gravity moves both balls alike: it adds nothing to their approach.
				var e: float = _restitution if ContactRule.bounces(vn, 0.0, _threshold) else 0.0
				var imp: Vector2 = nrm * (-(1.0 + e) * vn * 0.5)
				_vel[i] = vi - imp
				_vel[j] = vj + imp
			_push[i] -= s
			_push[j] += s


## The readable rule that solve_pairs() writes out for a pair with one ball held from
## behind: the free ball's velocity after it meets a ball that does not give way. `v` is
## the free ball's velocity, `away` the unit normal from the held ball to it. Only a ball
## moving into the held one is answered; it bounces with `restitution` when it comes in
## faster than `threshold` (gravity's approach this step, `gravity_dt`, not counted: see
## ContactRule), else it loses its normal speed.
static func off_held(
	v: Vector2, away: Vector2, gravity_dt: Vector2, restitution: float, threshold: float
) -> Vector2:
	var vn: float = v.dot(away)
	if vn >= 0.0:
		return v
	var bounces: bool = ContactRule.bounces(vn, gravity_dt.dot(away), threshold)
	var e: float = restitution if bounces else 0.0
	return v - away * ((1.0 + e) * vn)
