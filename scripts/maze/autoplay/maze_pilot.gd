class_name MazePilot
extends RefCounted
## The autoplay's hand on the board: each physics step it looks at every ball and picks one
## tilt for all of them.
##
## On a grid maze it first gathers the balls: the MazeSlidePlanner searches hard tilts held
## until the balls stop (slides) and tilts braked after 1-3 cells (steps) for the quickest
## way to herd every ball into one cell in or near the goal, and the pilot plays each move,
## re-planning whenever the balls end somewhere the plan did not expect (and remembering
## what really happened, so the next plan does not repeat the mistake). A plan that cannot
## gather them yet still brings them nearer, and the pilot plans again from there. Then it
## rolls the pack along its path (MazeNav) into the goal circle and brakes there. A wall off
## the grid's lines (slanted, or an end moved off a grid point) is drawn onto the grid
## (MazeGrid) and planned with like the rest. On a board with no grid, or when planning
## fails, it steers the ball nearest the goal.
## In hard mode the plans never roll a ball into a black hole's cell (a step stops short of
## it), and a MazeHoleGuard vets every tilt on a private copy of the board.
## The seed's random number picks the gains, the tilt strength and the order plans try
## moves in, so seeds play differently and the same seed always plays the same.

enum Phase { PLAN, MOVE, HERD, LEAD }

## A move ends when no ball has moved more than SETTLE_DRIFT px in SETTLE_SECONDS (balls
## pressed together into a corner jostle, so their speed alone never settles).
const SETTLE_DRIFT := 1.0
const SETTLE_SECONDS := 0.15
const MOVE_TIMEOUT := 5.0
## The pack counts as together while every ball is within this of its centre, px.
const PACK_RADIUS := 24.0
## A herded pack this spread out has split: gather again.
const HERD_GIVE_UP_SPREAD := 45.0
## A herded pack whose centre moved less than STALL_DRIFT px in STALL_SECONDS is stuck.
const STALL_SECONDS := 1.0
const STALL_DRIFT := 2.0
## Seconds the pack may sit in the goal without winning before it is gathered again.
const GOAL_PATIENCE := 3.0
## A step rolls at most this share of the speed cap and plans to stop braking at
## STEP_BRAKE px/s² (a full tilt brakes at ~1700), or on rolling friction alone while balls
## wait at walls; the last px it slows at STEP_APPROACH_RATE px/s per px left.
const STEP_SPEED_SHARE := 0.9
const STEP_BRAKE := 500.0
const STEP_APPROACH_RATE := 7.0
## A step is done once the movers stop within STEP_DONE_SLACK px short of its end or
## STEP_OVERSHOOT px past it (still in the cell it aimed for).
const STEP_STUCK_SECONDS := 0.5
const STEP_DONE_SLACK := 2.5
const STEP_OVERSHOOT := 10.0
## Re-plans allowed before the pilot falls back to steering single balls.
const MAX_PLANS := 60
## While steering single balls on a grid maze, the pilot tries to gather again this often,
## seconds (the balls have moved, so a plan may work now).
const LEAD_PATIENCE := 4.0

var nav: MazeNav
var grid: MazeGrid
var planner: MazeSlidePlanner
var phase: Phase = Phase.PLAN
## Continuous steering (herding, centring, leading), with the seed's gains.
var steering: MazeSteering
## Tilt of a hard move, degrees per axis.
var hard_tilt := 12.0
## Plans made so far.
var plans_made := 0
## Slides the physics did differently from the grid model, learned as the game goes.
var corrections := 0

var _level: BoardLevel
var _guard: MazeHoleGuard
var _rng: RandomNumberGenerator
var _dt := 1.0 / 120.0
var _move := 0
var _move_time := 0.0
var _still_time := 0.0
var _settle_mark := PackedVector2Array()
var _expected := PackedInt32Array()
var _move_start := PackedInt32Array()
## The balls' cells (sorted) when the move began.
var _move_cells := PackedInt32Array()
var _origin := PackedVector2Array()
var _step_done := false
var _hard := false
## True while the plan being played ends with every ball gathered.
var _gathering := false
var _herd_failures := {}
var _herd_cell := -1
var _herd_time := 0.0
var _herd_mark := Vector2.ZERO
var _goal_time := 0.0
var _lead_time := 0.0
## Rolling friction's slowing on a flat board, px/s².
var _coast_decel := 78.125


## A pilot for `level` (holes avoided when `hard_mode`), stepping `dt` seconds per call,
## with gains drawn from `rng`.
func _init(level: BoardLevel, hard_mode: bool, rng: RandomNumberGenerator, dt: float) -> void:
	_level = level
	_rng = rng
	_dt = dt
	_hard = hard_mode
	nav = MazeNav.new(level, hard_mode)
	grid = MazeGrid.new(level, hard_mode)
	if hard_mode:
		_guard = MazeHoleGuard.new(level, dt)
	if grid.is_grid:
		planner = MazeSlidePlanner.new(grid, nav)
	else:
		phase = Phase.LEAD
	var tuning := level.tuning as PhysicsTuning
	_coast_decel = tuning.rolling_friction if tuning != null else 78.125
	steering = MazeSteering.new(level, nav, tuning.max_speed if tuning != null else 93.75)
	steering.gain = rng.randf_range(0.15, 0.3)
	steering.lookahead = rng.randf_range(9.0, 15.0)
	steering.cruise = rng.randf_range(0.5, 0.8)
	hard_tilt = rng.randf_range(9.0, 12.0)


## The tilt (degrees per axis) for balls at `positions` moving at `velocities`.
func decide(positions: PackedVector2Array, velocities: PackedVector2Array) -> Vector2:
	var tilt := _steer(positions, velocities)
	if _guard != null:
		tilt = _guard.filter(tilt, positions, velocities)
	return tilt


func _steer(positions: PackedVector2Array, velocities: PackedVector2Array) -> Vector2:
	if positions.is_empty():
		return Vector2.ZERO
	if phase == Phase.PLAN:
		_plan(positions)
	match phase:
		Phase.MOVE:
			return _hold_move(positions, velocities)
		Phase.HERD:
			return _herd(positions, velocities)
	if planner != null and plans_made < MAX_PLANS:
		_lead_time += _dt
		if _lead_time >= LEAD_PATIENCE:
			_lead_time = 0.0
			phase = Phase.PLAN
			return Vector2.ZERO
	return steering.lead(positions, velocities)


func _plan(positions: PackedVector2Array) -> void:
	plans_made += 1
	if plans_made > MAX_PLANS:
		phase = Phase.LEAD
		return
	# Slides and steps in both modes: a step stops a ball short of a hole, or of the far
	# wall of a long corridor, and often gathers the balls sooner.
	var order := _shuffled(MazeGrid.MOVES)
	var cells := planner.cells_of(positions)
	_gathering = planner.plan(cells, order)
	if planner.moves.is_empty():
		phase = Phase.LEAD
		return
	# A plan that does not gather still brings the balls nearer: play it, then plan again.
	_move = 0
	_start_move(cells, positions)


# Moves 0 .. count-1 in the order the seed's random number shuffles them to.
func _shuffled(count: int) -> PackedInt32Array:
	var order := PackedInt32Array()
	for m in count:
		order.append(m)
	for i in range(order.size() - 1, 0, -1):
		var j := _rng.randi_range(0, i)
		var t := order[i]
		order[i] = order[j]
		order[j] = t
	return order


func _start_move(cells: PackedInt32Array, positions: PackedVector2Array) -> void:
	if _move >= planner.moves.size():
		if _gathering:
			_begin_herd(positions)
		else:
			phase = Phase.PLAN
		return
	phase = Phase.MOVE
	_move_time = 0.0
	_still_time = 0.0
	_settle_mark = positions.duplicate()
	_expected = planner.predict(cells, planner.moves[_move])
	_move_cells = cells.duplicate()
	_move_start = PackedInt32Array()
	for p in positions:
		_move_start.append(grid.cell_at(p))
	_origin = positions.duplicate()


func _hold_move(positions: PackedVector2Array, velocities: PackedVector2Array) -> Vector2:
	_move_time += _dt
	var move := planner.moves[_move]
	var tilt := Vector2(MazeGrid.direction(move)) * hard_tilt
	var done := false
	if MazeGrid.is_step(move):
		tilt = _step_tilt(positions, velocities, move)
		# A step whose balls stopped short (a ball ahead, a cap) is over too.
		done = _step_done or (_move_time > STEP_STUCK_SECONDS and _settled(positions))
	else:
		done = _settled(positions)
	if not done and _move_time <= MOVE_TIMEOUT:
		return tilt
	var cells := planner.cells_of(positions)
	if (
		MazeSteering.spread(positions) <= PACK_RADIUS
		and not planner.is_banned(_pack_cell(positions))
	):
		_begin_herd(positions)
	elif cells != _expected:
		_learn(positions)
		phase = Phase.PLAN
	else:
		_move += 1
		_start_move(cells, positions)
	return Vector2.ZERO


# True once no ball moved more than SETTLE_DRIFT in the last SETTLE_SECONDS.
func _settled(positions: PackedVector2Array) -> bool:
	_still_time += _dt
	if _still_time < SETTLE_SECONDS:
		return false
	var drift := 0.0
	for i in mini(positions.size(), _settle_mark.size()):
		drift = maxf(drift, positions[i].distance_to(_settle_mark[i]))
	var settled := drift < SETTLE_DRIFT and positions.size() == _settle_mark.size()
	_settle_mark = positions.duplicate()
	_still_time = 0.0
	return settled


# A step: the balls that are free to go the whole way travel its cells and stop (they all
# move alike in the open, so the mean of their travel is steered). Balls that meet a wall
# sooner wait there; while any waits, the tilt never turns back (it would roll them off
# their wall) and the movers coast to a stop on rolling friction alone. Sets `_step_done`.
func _step_tilt(
	positions: PackedVector2Array, velocities: PackedVector2Array, move: int
) -> Vector2:
	var dir := Vector2(MazeGrid.direction(move))
	var goes := PackedFloat32Array()
	var length := 0.0
	for i in _move_start.size():
		goes.append(grid.travel(_move_start[i], grid.slide(_move_start[i], move)))
		length = maxf(length, goes[i])
	var travelled := 0.0
	var speed := 0.0
	var moving := 0
	for i in mini(positions.size(), goes.size()):
		if goes[i] < length - 0.5:
			continue
		travelled += (positions[i] - _origin[i]).dot(dir)
		speed += velocities[i].dot(dir)
		moving += 1
	if moving == 0 or length <= 0.0:
		_step_done = true
		return Vector2.ZERO
	var waiting := moving < mini(positions.size(), goes.size())
	var left := length - travelled / float(moving)
	speed /= float(moving)
	var brake := _coast_decel * 0.8 if waiting else STEP_BRAKE
	var wanted := minf(steering.max_speed * STEP_SPEED_SHARE, sqrt(2.0 * brake * absf(left)))
	wanted = signf(left) * minf(wanted, absf(left) * STEP_APPROACH_RATE)
	_step_done = absf(speed) < 4.0 and left < STEP_DONE_SLACK and left > -STEP_OVERSHOOT
	var amount := (wanted - speed) * steering.gain
	if left > STEP_DONE_SLACK and absf(amount) < MazeSteering.MIN_NUDGE_DEG:
		amount = MazeSteering.MIN_NUDGE_DEG
	return dir * clampf(amount, 0.0 if waiting else -hard_tilt, hard_tilt)


func _begin_herd(positions: PackedVector2Array) -> void:
	phase = Phase.HERD
	_herd_cell = _pack_cell(positions)
	_herd_time = 0.0
	_goal_time = 0.0
	_herd_mark = Vector2(INF, INF)


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
	# What this move did to these balls together is remembered as it is (balls bump into
	# each other the same way again); what each lone ball did teaches the grid.
	planner.remember(_move_cells, dir, planner.cells_of(positions))
	for i in mini(positions.size(), _move_start.size()):
		if _touches_another(positions, i):
			continue  # stopped by a ball, not by the board: nothing to learn about the cell
		var from := _move_start[i]
		var landed := grid.cell_at(positions[i])
		if grid.slide(from, dir) != landed:
			grid.slides[from * MazeGrid.MOVES + dir] = landed
			corrections += 1


# True when ball `i` rests against another ball (within a ball's width and a little).
func _touches_another(positions: PackedVector2Array, i: int) -> bool:
	var reach := _level.ball_radius * 2.0 + 2.0
	for o in positions.size():
		if o != i and positions[o].distance_to(positions[i]) <= reach:
			return true
	return false


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
	var stalled := false
	if _herd_time >= STALL_SECONDS:
		stalled = centre.distance_to(_herd_mark) < STALL_DRIFT and not near_goal
		_herd_mark = centre
		_herd_time = 0.0
	var split := MazeSteering.spread(positions) > HERD_GIVE_UP_SPREAD and not near_goal
	if split or stalled or _goal_time > GOAL_PATIENCE:
		# The pack split or stuck on the way, or sits in the goal too spread out to fit:
		# gather again, and after two failures from one cell never herd from there again.
		var failures: int = _herd_failures.get(_herd_cell, 0) + 1
		_herd_failures[_herd_cell] = failures
		if failures >= 2:
			planner.ban(_herd_cell)
		phase = Phase.PLAN
		return Vector2.ZERO
	if near_goal:
		return steering.centre_pack(positions, velocities)
	return steering.follow_paths(positions, velocities)
