class_name GoalDip
extends RefCounted
## The maze's goal as a shallow dish: a ball whose centre is inside the goal's rim (the rule's
## edge, the dip the floor shader draws) is pulled toward the middle, harder than the
## steepest tilt pulls it away, and slowed, so a ball that rolls in stays in while the
## player fetches the others. A play trial saw balls roll straight across the goal and out
## again ("1 / 4" back to "0 / 4"). A game rule, not physics: it changes the balls'
## velocities before each step (BallWorld.before_step).

## The dish's pull at and near its rim, as a share of one axis's full tilt pull
## (MAX_TILT_DEG): the board tilted fully on both axes pulls √2 (1.41) times that.
const HOLD_SHARE := 1.6
## Where the full diagonal tilt's pull is balanced by the dish's, from the middle (px): nearer the
## middle the pull falls off in proportion, so a held ball rests there instead of jittering.
const REST_OFFSET_PX := 4.0
## How fast a ball in the dish loses its speed (1/s): it settles within about a second.
const DAMPING := 5.0

const TiltInput := preload("res://scripts/maze/rules/tilt_input.gd")

var _world: BallWorld
var _centre := Vector2.ZERO
var _radius := 0.0
var _max_pull := 0.0
var _stiffness := 0.0


## The dip of `level`'s goal in `world` (a maze world built from it).
func _init(world: BallWorld, level: BoardLevel) -> void:
	_world = world
	_centre = level.goal_center
	_radius = level.goal_radius
	var steepest := (
		MazeTilt.gravity(Vector2(TiltInput.MAX_TILT_DEG, 0.0), world.tuning.tilt_gravity).x
	)
	_max_pull = steepest * HOLD_SHARE
	_stiffness = steepest * sqrt(2.0) / REST_OFFSET_PX


## The pull (px/s²) on a ball at `offset` from the goal's middle: toward the middle,
## growing with the distance up to the rim's pull; none outside the rim.
func pull_at(offset: Vector2) -> Vector2:
	var distance := offset.length()
	if distance >= _radius or distance <= 0.0:
		return Vector2.ZERO
	return -offset / distance * minf(_stiffness * distance, _max_pull)


## Pulls and slows every ball inside the rim for a step of `dt` seconds (the world calls it
## before each step).
func apply(dt: float) -> void:
	var ids := _world.get_ids()
	var positions := _world.get_positions()
	var slowing := exp(-DAMPING * dt)
	for i in ids.size():
		var offset := positions[i] - _centre
		if offset.length_squared() >= _radius * _radius:
			continue
		var velocity := _world.get_ball_velocity(ids[i])
		_world.set_ball_velocity(ids[i], velocity * slowing + pull_at(offset) * dt)
