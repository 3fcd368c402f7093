extends RefCounted
## The autoplay's hand on the board: each physics step it looks at every ball and picks one
## tilt for all of them.
##
## On a grid maze it first gathers the balls: the MazeSlidePlanner finds hard tilts that
## herd every ball into one cell near the goal, and the pilot holds each tilt until the
## balls stop, re-planning whenever the balls end somewhere the plan did not expect. Then
## it rolls the pack along its path (MazeNav) into the goal circle and brakes there. On a
## board that is not a grid, or when gathering fails, it steers the ball nearest the goal.
## The seed's random number picks the gains, the tilt strength and the order plans try
## directions in, so seeds play differently and the same seed always plays the same.

enum Phase { PLAN, MOVE, HERD, LEAD }

const MazeNav := preload("res://scripts/maze/maze_nav.gd")
const MazeGrid := preload("res://scripts/maze/maze_grid.gd")
const MazeSlidePlanner := preload("res://scripts/maze/maze_slide_planner.gd")
const TiltInput := preload("res://scripts/maze/tilt_input.gd")
## A move ends when every ball has been slower than this (px/s) for SETTLE_SECONDS.
const SETTLE_SPEED := 3.0
const SETTLE_SECONDS := 0.1
const MOVE_TIMEOUT := 5.0
## The pack counts as together while every ball is within this of its centre, px.
const PACK_RADIUS := 30.0
## Re-plans allowed before the pilot falls back to steering single balls.
const MAX_PLANS := 60

var nav: MazeNav
var grid: MazeGrid
var planner: MazeSlidePlanner
var phase: Phase = Phase.PLAN
## Degrees of tilt per px/s of velocity error.
var gain := 0.2
## How far ahead along the path a ball aims, in px.
var lookahead := 12.0
## Cruising speed as a share of the board's speed cap.
var cruise := 0.85
## Tilt of a hard move, degrees per axis.
var hard_tilt := 12.0
## Plans made so far.
var plans_made := 0

var _level: BoardLevel
var _rng: RandomNumberGenerator
var _dt := 1.0 / 120.0
var _max_speed := 93.75
var _move := 0
var _move_time := 0.0
var _still_time := 0.0
var _expected := PackedInt32Array()


## A pilot for `level` (holes avoided when `hard_mode`), stepping `dt` seconds per call,
## with gains drawn from `rng`.
func _init(level: BoardLevel, hard_mode: bool, rng: RandomNumberGenerator, dt: float) -> void:
	_level = level
	_rng = rng
	_dt = dt
	nav = MazeNav.new(level, hard_mode)
	grid = MazeGrid.new(level)
	if grid.is_grid and not hard_mode:
		planner = MazeSlidePlanner.new(grid, nav)
	else:
		phase = Phase.LEAD
	var tuning := level.tuning as PhysicsTuning
	if tuning != null:
		_max_speed = tuning.max_speed
	gain = rng.randf_range(0.15, 0.3)
	lookahead = rng.randf_range(9.0, 15.0)
	cruise = rng.randf_range(0.5, 0.8)
	hard_tilt = rng.randf_range(9.0, 12.0)


## The tilt (degrees per axis) for balls at `positions` moving at `velocities`.
func decide(positions: PackedVector2Array, velocities: PackedVector2Array) -> Vector2:
	if positions.is_empty():
		return Vector2.ZERO
	if phase == Phase.PLAN:
		_plan(positions)
	match phase:
		Phase.MOVE:
			return _hold_move(positions, velocities)
		Phase.HERD:
			return _herd(positions, velocities)
	return _lead(positions, velocities)


func _plan(positions: PackedVector2Array) -> void:
	plans_made += 1
	if plans_made > MAX_PLANS:
		phase = Phase.LEAD
		return
	var order := PackedInt32Array([0, 1, 2, 3, 4, 5, 6, 7])
	for i in range(order.size() - 1, 0, -1):
		var j := _rng.randi_range(0, i)
		var t := order[i]
		order[i] = order[j]
		order[j] = t
	var cells := planner.cells_of(positions)
	var gathered := planner.plan(cells, order)
	if not gathered:
		phase = Phase.LEAD
		return
	_move = 0
	_start_move(cells)


func _start_move(cells: PackedInt32Array) -> void:
	if _move >= planner.moves.size():
		phase = Phase.HERD
		return
	phase = Phase.MOVE
	_move_time = 0.0
	_still_time = 0.0
	_expected = planner.predict(cells, planner.moves[_move])


func _hold_move(positions: PackedVector2Array, velocities: PackedVector2Array) -> Vector2:
	_move_time += _dt
	var fastest := 0.0
	for v in velocities:
		fastest = maxf(fastest, v.length())
	_still_time = _still_time + _dt if fastest < SETTLE_SPEED else 0.0
	var settled := _still_time >= SETTLE_SECONDS and _move_time > 0.2
	if settled or _move_time > MOVE_TIMEOUT:
		var cells := planner.cells_of(positions)
		if _spread(positions) <= PACK_RADIUS:
			phase = Phase.HERD
			return Vector2.ZERO
		if cells != _expected:
			phase = Phase.PLAN
			return Vector2.ZERO
		_move += 1
		_start_move(cells)
		if phase != Phase.MOVE:
			return Vector2.ZERO
	var dir := Vector2(MazeGrid.DIRECTIONS[planner.moves[_move]])
	return dir * hard_tilt


# Rolls the gathered pack along its centre's path to the goal, braking near the centre.
func _herd(positions: PackedVector2Array, velocities: PackedVector2Array) -> Vector2:
	var centre := Vector2.ZERO
	var mean_v := Vector2.ZERO
	for i in positions.size():
		centre += positions[i]
		mean_v += velocities[i]
	centre /= float(positions.size())
	mean_v /= float(positions.size())
	var spread := _spread(positions)
	var near_goal := centre.distance_to(_level.goal_center) < _level.goal_radius
	if spread > PACK_RADIUS and not near_goal:
		phase = Phase.PLAN
		return Vector2.ZERO
	var aim := _level.goal_center if near_goal else nav.carrot(centre, lookahead)
	return TiltInput.clamp_tilt(_velocity_tilt(aim, centre, mean_v, cruise))


# Steers the ball nearest the goal that is not in yet; balls already in pull gently back.
func _lead(positions: PackedVector2Array, velocities: PackedVector2Array) -> Vector2:
	var leader := -1
	var leader_distance := INF
	var hold := Vector2.ZERO
	for i in positions.size():
		if positions[i].distance_to(_level.goal_center) < _level.goal_radius - 2.0:
			hold += _velocity_tilt(_level.goal_center, positions[i], velocities[i], 0.4)
			continue
		var d := nav.distance_at(positions[i])
		if d < leader_distance:
			leader_distance = d
			leader = i
	var tilt := hold * 0.25
	if leader >= 0:
		var target := nav.carrot(positions[leader], lookahead)
		tilt += _velocity_tilt(target, positions[leader], velocities[leader], cruise)
	return TiltInput.clamp_tilt(tilt)


# The tilt that turns velocity `v` toward moving at `share` of the cap toward `target`,
# slowing down as the target nears.
func _velocity_tilt(target: Vector2, p: Vector2, v: Vector2, share: float) -> Vector2:
	var to := target - p
	var speed := minf(_max_speed * share, to.length() * 3.0)
	var want := to.normalized() * speed if to.length() > 0.01 else Vector2.ZERO
	return (want - v) * gain


# Largest distance of a ball from the balls' centre, px.
static func _spread(positions: PackedVector2Array) -> float:
	var centre := Vector2.ZERO
	for p in positions:
		centre += p
	centre /= float(maxi(positions.size(), 1))
	var spread := 0.0
	for p in positions:
		spread = maxf(spread, p.distance_to(centre))
	return spread
