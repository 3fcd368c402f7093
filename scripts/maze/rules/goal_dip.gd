class_name GoalDip
extends RefCounted
## The maze's goal as a shallow dish: a ball whose drawn disc reaches over the goal's rim (the
## dip the floor shader draws) is in the goal: it counts, and it is pulled toward the middle,
## harder than the steepest tilt pulls it away, and slowed, so a ball that rolls in stays in
## while the player fetches the others. A play trial saw balls roll straight across the goal
## and out again ("1 / 4" back to "0 / 4"); a later one saw a ball drawn over the rim, its
## centre just outside, neither counted nor pulled, and read it as the goal failing.
## A game rule, not physics: it changes the balls' velocities before each step
## (BallWorld.before_step).

## The dish's pull at and near its rim, as a share of one axis's full tilt pull
## (MAX_TILT_DEG): more than any tilt the keys or a stick give (they reach full tilt on one
## axis, or 8.5 degrees on both), so a held ball stays; the joystick dragged into its very
## corner (12 degrees on both axes, 1.41 times one axis) can still tip a ball out.
const HOLD_SHARE := 1.3
## Where one axis's full tilt pull is balanced by the dish's, from the middle (px): nearer the
## middle the pull falls off in proportion, so a held ball rests there instead of jittering.
const REST_OFFSET_PX := 4.0
## How fast a ball in the dish loses its speed (1/s): it settles within about a second.
const DAMPING := 5.0

var _world: BallWorld
var _centre := Vector2.ZERO
var _radius := 0.0
## How far from the middle a ball's centre is in the goal: the rim plus a ball's radius, so
## any ball whose disc overlaps the drawn dip counts as the player sees it.
var _reach := 0.0
var _max_pull := 0.0
var _stiffness := 0.0
## The centre lines of the walls that cross the dish (pairs of ends): a ball on the far side
## of one is in the next corridor, not in the dish, and is not pulled into the wall.
var _walls_across := PackedVector2Array()


## The dip of `level`'s goal in `world` (a maze world built from it).
func _init(world: BallWorld, level: BoardLevel) -> void:
	_world = world
	_centre = level.goal_center
	_radius = level.goal_radius
	_reach = _radius + level.ball_radius
	var steepest := (
		MazeTilt.gravity(Vector2(TiltInput.MAX_TILT_DEG, 0.0), world.tuning.tilt_gravity).x
	)
	_max_pull = steepest * HOLD_SHARE
	var reach := _reach + level.wall_width
	for i in range(0, level.walls.size() - 1, 2):
		var a := level.walls[i]
		var b := level.walls[i + 1]
		if Geometry2D.get_closest_point_to_segment(_centre, a, b).distance_to(_centre) < reach:
			_walls_across.append(a)
			_walls_across.append(b)
	_stiffness = steepest / REST_OFFSET_PX


## The pull (px/s²) on a ball at `offset` from the goal's middle: toward the middle,
## growing with the distance up to the rim's pull; none once the ball's disc is clear of the
## rim, and none when a wall stands between the ball and the middle.
func pull_at(offset: Vector2) -> Vector2:
	var distance := offset.length()
	if distance >= _reach or distance <= 0.0 or _walled_off(offset):
		return Vector2.ZERO
	return -offset / distance * minf(_stiffness * distance, _max_pull)


## True when a ball centred at `at` is in the goal: its disc overlaps the drawn dip and no
## wall stands between it and the middle.
func holds(at: Vector2) -> bool:
	var offset := at - _centre
	return offset.length_squared() < _reach * _reach and not _walled_off(offset)


## The balls in the goal now (`holds`), over every ball in the world.
func count_inside() -> int:
	var inside := 0
	for at in _world.get_positions():
		if holds(at):
			inside += 1
	return inside


# True when a wall's centre line crosses the line from the middle to `offset`.
func _walled_off(offset: Vector2) -> bool:
	var at := _centre + offset
	for i in range(0, _walls_across.size(), 2):
		var crossing: Variant = Geometry2D.segment_intersects_segment(
			_centre, at, _walls_across[i], _walls_across[i + 1]
		)
		if crossing != null:
			return true
	return false


## Pulls and slows every ball in the goal (`holds`) for a step of `dt` seconds (the world calls it
## before each step). It touches no other ball: each it steers wakes alone.
func apply(dt: float) -> void:
	var ids := _world.get_ids()
	var positions := _world.get_positions()
	var slowing := exp(-DAMPING * dt)
	for i in ids.size():
		var offset := positions[i] - _centre
		if offset.length_squared() >= _reach * _reach:
			continue
		var pull := pull_at(offset)
		if pull == Vector2.ZERO:
			continue  # walled off (or dead centre): left to roll as anywhere else
		var velocity := _world.get_ball_velocity(ids[i])
		# this ball only: the others keep sleeping (set_ball_velocity woke them all)
		_world.set_ball_velocity(ids[i], velocity * slowing + pull * dt, false)
