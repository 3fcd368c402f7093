class_name MazeRules
extends RefCounted
## The tilt maze's rules: owns the BallWorld of one board, turns the tilt into gravity and
## rolling friction the way the seed does, runs the clock, and decides win and loss.
## Never draws; the view reads positions and listens to the signals.
##
## Life of a game: READY (balls at the start, waiting for the first press of the joystick),
## PLAYING (the world steps, the clock runs), then WON or LOST until `reset()`.

## The game began (the joystick was pressed).
signal started
## Every ball is in the goal (GoalDip.holds); `seconds` is the attempt's time.
signal won(seconds: float)
## A ball fell into black hole `hole_index` (hard mode); the game is over.
signal lost(hole_index: int)
## The balls went back to their starts (Space, a mode switch, or a restart).
signal game_reset
## Hard mode was switched on or off.
signal mode_changed(hard: bool)
## A ball hit a wall at `impact_speed` px/s (for sounds).
signal wall_bumped(impact_speed: float)
## The number of balls in the goal changed.
signal goal_count_changed(balls_in_goal: int)

enum State { READY, PLAYING, WON, LOST }

## The tilt is kept in whole hundredths of a degree (too fine to feel), so a replay stores
## it as whole numbers and plays it back bit for bit.
const TILT_STEPS_PER_DEGREE := 100.0

## The board being played.
var level: BoardLevel
## The simulation; rebuilt on every reset.
var world: BallWorld
## Where the game is in its life.
var state: State = State.READY
## True when black holes are on the board.
var hard_mode := false
## Seconds of simulated play in this attempt (stops at a win or loss).
var elapsed := 0.0
## Current tilt in degrees per axis (+x rolls right, +y rolls down).
var tilt := Vector2.ZERO
## The hole a ball fell into, or -1.
var lost_hole := -1
## Balls in the goal now: their disc overlaps the goal's dish (GoalDip.holds).
var balls_in_goal := 0

var _step_dt := 1.0 / 120.0
## The goal's dish, which holds the balls that roll in (GoalDip).
var _dip: GoalDip


## Builds the world for `board` (a maze BoardLevel) in easy or hard mode.
func _init(board: BoardLevel, hard := false) -> void:
	level = board
	hard_mode = hard
	_rebuild()


## True when the board could be built (a bad board leaves `world` null and reports it).
func is_ready() -> bool:
	return world != null


## Starts the clock and the physics (the seed's "click the joystick to start").
## Does nothing unless the game is waiting at the start.
func start() -> void:
	if state != State.READY or world == null:
		return
	state = State.PLAYING
	started.emit()


## True while the balls roll and the clock runs.
func is_playing() -> bool:
	return state == State.PLAYING


## True once the game ended (won or lost) and waits for a reset.
func is_over() -> bool:
	return state == State.WON or state == State.LOST


## Sets the board's tilt in degrees per axis, clamped to ±12°. Gravity and friction follow
## at once; the view eases its own picture of the board toward it.
func set_tilt(tilt_deg: Vector2) -> void:
	var steps := (TiltInput.clamp_tilt(tilt_deg) * TILT_STEPS_PER_DEGREE).round()
	tilt = steps / TILT_STEPS_PER_DEGREE
	_apply_tilt()


## Puts the balls back at their starts, flattens the board and waits for the joystick.
func reset() -> void:
	_rebuild()
	game_reset.emit()


## Switches hard mode (black holes) on or off; always resets, as the seed's H and E do.
func set_hard_mode(hard: bool) -> void:
	var changed := hard != hard_mode
	hard_mode = hard
	reset()
	if changed:
		mode_changed.emit(hard_mode)


## Runs the physics for `delta` seconds of real time in whole fixed steps (only while
## playing). Returns the number of steps run. The world's accumulator is the only one: it
## keeps the remainder for the next frame and drops the backlog of a long hitch (a
## breakpoint, a window drag) instead of replaying seconds of physics at once.
func advance(delta: float) -> int:
	if state != State.PLAYING or not is_finite(delta) or delta <= 0.0:
		return 0
	_apply_tilt()
	var steps := world.advance(delta)
	_after_steps(steps)
	return steps


## One fixed physics step, then the clock, the goal count and the win check.
func step() -> void:
	if state != State.PLAYING:
		return
	_apply_tilt()
	world.step(_step_dt)
	_after_steps(1)


## Runs exactly `count` fixed steps as one frame, as `advance` does for a frame that ran
## `count` steps; replays and the ghost play recorded frames with it. Returns the steps run
## (0 unless playing).
func run_steps(count: int) -> int:
	if state != State.PLAYING or count <= 0:
		return 0
	_apply_tilt()
	for i in count:
		world.step(_step_dt)
	_after_steps(count)
	return count


## After a win the balls roll on for `delta` seconds (the clock stopped, nothing judged), so
## the dip gathers them in as the board levels: a play trial saw the finished ball frozen on
## the dip's rim, half outside it, on a board frozen tilted. Returns the steps run (0 unless
## won). What it moves is never recorded: a replay ends at the win.
func settle(delta: float) -> int:
	if state != State.WON or world == null or not is_finite(delta) or delta <= 0.0:
		return 0
	_apply_tilt()
	return world.advance(delta)


## Length of one physics step, in seconds.
func step_seconds() -> float:
	return _step_dt


## Ball centres, dense, in the order of `world.get_ids()` (for drawing in one batch).
func ball_positions() -> PackedVector2Array:
	return world.get_positions() if world != null else PackedVector2Array()


## How many balls the board starts with.
func ball_total() -> int:
	return level.ball_starts.size() if level != null else 0


## Balls that fell into holes (0 or 1: the first ends the game).
func balls_lost() -> int:
	return 1 if lost_hole >= 0 else 0


## Balls still on the board (the board's count, less any that fell into a hole).
func balls_left() -> int:
	return world.ball_count() if world != null else 0


## False once the game cannot be won: every ball must reach the goal, so a ball lost into a
## hole ends the run's chance (the view says so at once and offers Retry).
func can_still_win() -> bool:
	return world != null and state != State.LOST and balls_left() == ball_total()


## The balls in the goal: each one whose drawn disc overlaps the dish's rim, with no wall
## between it and the middle (GoalDip.holds). The seed counted a ball's centre inside the
## rim; a play trial saw a ball drawn over the rim left uncounted and read it as a fault.
func count_in_goal() -> int:
	return _dip.count_inside() if world != null and _dip != null else 0


func _rebuild() -> void:
	state = State.READY
	elapsed = 0.0
	tilt = Vector2.ZERO
	lost_hole = -1
	balls_in_goal = 0
	world = null
	_dip = null
	if level == null or not level.is_maze():
		var got := "no board" if level == null else "the pachinko board '%s'" % level.board_id
		push_error("MazeRules: needs a maze board, got %s" % got)
		return
	world = BoardWorldFactory.build(level, hard_mode)
	if world == null:
		push_error("MazeRules: could not build board '%s'" % level.board_id)
		return
	if world.tuning != null and world.tuning.fixed_hz > 0:
		_step_dt = 1.0 / float(world.tuning.fixed_hz)
	if world.ball_count() == 0:
		for start_pos in level.ball_starts:
			world.spawn_ball(start_pos, Vector2.ZERO, level.ball_radius)
	_dip = GoalDip.new(world, level)  # kept: the world's callable does not hold it
	world.before_step = _dip.apply
	world.ball_fell_in_hole.connect(_on_ball_fell_in_hole)
	world.wall_hit.connect(_on_wall_hit)
	_apply_tilt()
	balls_in_goal = count_in_goal()


func _apply_tilt() -> void:
	if world == null:
		return
	MazeTilt.apply(world, tilt)


## After `steps` world steps: the clock and the goal count, unless a ball fell in a hole
## during them (the game is over and the clock stopped).
func _after_steps(steps: int) -> void:
	if state != State.PLAYING:
		return
	elapsed += steps * _step_dt
	_update_goal()


func _update_goal() -> void:
	var inside := count_in_goal()
	if inside != balls_in_goal:
		balls_in_goal = inside
		goal_count_changed.emit(inside)
	if inside == ball_total() and inside > 0 and world.ball_count() == ball_total():
		state = State.WON
		won.emit(elapsed)


func _on_ball_fell_in_hole(_ball_id: int, hole_index: int) -> void:
	if state != State.PLAYING:
		return
	lost_hole = hole_index
	state = State.LOST
	lost.emit(hole_index)


func _on_wall_hit(_ball_id: int, _wall_index: int, impact_speed: float) -> void:
	wall_bumped.emit(impact_speed)
