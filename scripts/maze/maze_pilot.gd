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
const PACK_RADIUS := 24.0
## A herded pack this spread out has split: gather again.
const HERD_GIVE_UP_SPREAD := 45.0
## Seconds the pack may sit in the goal without winning before it is gathered again.
const GOAL_PATIENCE := 3.0
## Smallest tilt that still moves a resting ball, with a margin, degrees.
const MIN_NUDGE_DEG := 1.0
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
## Slides the physics did differently from the grid model, learned as the game goes.
var corrections := 0

var _level: BoardLevel
var _rng: RandomNumberGenerator
var _dt := 1.0 / 120.0
var _max_speed := 93.75
var _move := 0
var _move_time := 0.0
var _still_time := 0.0
var _expected := PackedInt32Array()
var _move_start := PackedInt32Array()
var _herd_failures := {}
var _herd_cell := -1
var _herd_time := 0.0
var _goal_time := 0.0


## A pilot for `level` (holes avoided when `hard_mode`), stepping `dt` seconds per call,
## with gains drawn from `rng`.
func _init(level: BoardLevel, hard_mode: bool, rng: RandomNumberGenerator, dt: float) -> void:
	_level = level
	_rng = rng
	_dt = dt
	nav = MazeNav.new(level, hard_mode)
	grid = MazeGrid.new(level, hard_mode)
	if grid.is_grid:
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
	_start_move(cells, positions)


func _start_move(cells: PackedInt32Array, positions: PackedVector2Array) -> void:
	if _move >= planner.moves.size():
		_begin_herd(positions)
		return
	phase = Phase.MOVE
	_move_time = 0.0
	_still_time = 0.0
	_expected = planner.predict(cells, planner.moves[_move])
	_move_start = PackedInt32Array()
	for p in positions:
		_move_start.append(grid.cell_at(p))


func _hold_move(positions: PackedVector2Array, velocities: PackedVector2Array) -> Vector2:
	_move_time += _dt
	var fastest := 0.0
	for v in velocities:
		fastest = maxf(fastest, v.length())
	_still_time = _still_time + _dt if fastest < SETTLE_SPEED else 0.0
	var settled := _still_time >= SETTLE_SECONDS and _move_time > 0.2
	if settled or _move_time > MOVE_TIMEOUT:
		var cells := planner.cells_of(positions)
		if _spread(positions) <= PACK_RADIUS and not planner.is_banned(_pack_cell(positions)):
			_begin_herd(positions)
			return Vector2.ZERO
		if cells != _expected:
			_learn(positions)
			phase = Phase.PLAN
			return Vector2.ZERO
		_move += 1
		_start_move(cells, positions)
		if phase != Phase.MOVE:
			return Vector2.ZERO
	var dir := Vector2(MazeGrid.DIRECTIONS[planner.moves[_move]])
	return dir * hard_tilt


func _begin_herd(positions: PackedVector2Array) -> void:
	phase = Phase.HERD
	_herd_cell = _pack_cell(positions)
	_herd_time = 0.0
	_goal_time = 0.0


# The cell under the middle of the balls.
func _pack_cell(positions: PackedVector2Array) -> int:
	var centre := Vector2.ZERO
	for p in positions:
		centre += p
	return grid.cell_at(centre / float(maxi(positions.size(), 1)))


# The balls did not end where the grid model said: remember where each one really went
# from its cell with this tilt, so the next plan does not repeat the same mistake.
func _learn(positions: PackedVector2Array) -> void:
	var dir := planner.moves[_move]
	for i in mini(positions.size(), _move_start.size()):
		var from := _move_start[i]
		var landed := grid.cell_at(positions[i])
		if grid.slide(from, dir) != landed:
			grid.slides[from * 8 + dir] = landed
			corrections += 1


# Rolls the gathered pack to the goal: each ball asks for the velocity that follows its own
# path, and the tilt serves their average (packed balls want nearly the same thing, and a
# ball a cell behind is led round the corner the others took). In the goal every ball asks
# for the centre, so the pack stops there.
func _herd(positions: PackedVector2Array, velocities: PackedVector2Array) -> Vector2:
	var centre := Vector2.ZERO
	for p in positions:
		centre += p
	centre /= float(positions.size())
	var near_goal := centre.distance_to(_level.goal_center) < _level.goal_radius * 0.7
	_herd_time += _dt
	if near_goal:
		_goal_time += _dt
	var split := _spread(positions) > HERD_GIVE_UP_SPREAD and not near_goal
	if split or _goal_time > GOAL_PATIENCE:
		# The pack split on the way, or sits in the goal too spread out to fit: gather again,
		# and after two failures from the same cell never herd from there again.
		var failures: int = _herd_failures.get(_herd_cell, 0) + 1
		_herd_failures[_herd_cell] = failures
		if failures >= 2:
			planner.ban(_herd_cell)
		phase = Phase.PLAN
		return Vector2.ZERO
	if near_goal:
		return _centre_pack(positions, velocities)
	var tilt := Vector2.ZERO
	for i in positions.size():
		var aim := nav.carrot(positions[i], lookahead)
		tilt += _velocity_tilt(aim, positions[i], velocities[i], cruise)
	return TiltInput.clamp_tilt(tilt / float(positions.size()))


# In the goal: slides the whole pack so the middle of its bounding box sits on the goal's
# centre. Every axis that still has to move gets at least MIN_NUDGE_DEG, enough to beat
# rolling friction (which holds a ball still below about 0.6°).
func _centre_pack(positions: PackedVector2Array, velocities: PackedVector2Array) -> Vector2:
	var lo := positions[0]
	var hi := positions[0]
	var mean_v := Vector2.ZERO
	for i in positions.size():
		lo = lo.min(positions[i])
		hi = hi.max(positions[i])
		mean_v += velocities[i]
	mean_v /= float(positions.size())
	var to := _level.goal_center - (lo + hi) * 0.5
	var want := (to * 3.0).limit_length(_max_speed * 0.4)
	var tilt := (want - mean_v) * gain
	for axis in 2:
		if absf(to[axis]) > 1.5 and absf(tilt[axis]) < MIN_NUDGE_DEG:
			tilt[axis] = signf(to[axis]) * MIN_NUDGE_DEG
	return TiltInput.clamp_tilt(tilt)


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
