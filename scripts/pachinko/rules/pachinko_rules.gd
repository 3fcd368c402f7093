class_name PachinkoRules
extends RefCounted
## The pachinko game without pictures: the cup, the flipper and launcher, payouts, the
## gutter and game over, over a BallWorld built from the board. Input arrives as calls
## (`start_game`, `press_flipper`, `drag_to`, `begin_charge`, `charge`, `release`); what
## happens leaves as past-tense signals. It never draws and never reads the input map.
## Its parts: the drawback, the handle, the upkeep of balls in play, ledger, bonus, gold pins.
## Flow: `start_game` fills the cup and loads a ball; a release fires it and loads the
## next; pockets pay into the cup; an empty cup with nothing loaded or in play ends it.

## The state changed (see State).
signal state_changed(state: State)
## A game began: the cup was filled.
signal game_started(cup: int)
## The number of balls in the cup changed.
signal cup_changed(cup: int)
## A ball moved from the cup into the launcher.
signal ball_loaded
## The flipper's drawback changed: power 0..100.
signal power_changed(power: float)
## A ball was fired up the rail with `power` and `speed` (px/s).
signal ball_launched(ball_id: int, power: float, speed: float)
## A shot too weak to clear the rail rolled back; the ball went back into the cup.
signal ball_returned(ball_id: int)
## A ball reached a pocket's special pin: it left play and `payout` balls went to the cup.
signal ball_won(ball_id: int, pocket: int, payout: int, at: Vector2)
## The gutter swallowed a ball.
signal ball_drained(ball_id: int)
## A ball resting too long got a small push.
signal ball_nudged(ball_id: int)
## The cup ran dry with nothing loaded or in play. `summary` is `stats()`.
signal game_ended(summary: Dictionary)

## INSTRUCTIONS: before the first game; PLAYING; GAME_OVER: the instructions are back.
enum State { INSTRUCTIONS, PLAYING, GAME_OVER }

## Power added per second while a key or button is held (full power in 1.6 s).
const CHARGE_PER_SECOND := FlipperDrawback.CHARGE_PER_SECOND
## Shot powers are kept in whole hundredths, so a replay stores them bit for bit.
const POWER_STEP := 0.01

## The board being played.
var level: BoardLevel
## The simulation; the view reads positions and pin hits from it.
var world: BallWorld
var state := State.INSTRUCTIONS
## Balls in the cup.
var cup := 0
## True while a ball sits in the launcher.
var loaded := false
## Balls left to shoot, the loaded one too: the count shown (the cup alone read 24 of 25).
var balls_to_shoot: int:
	get:
		return cup + (1 if loaded else 0)
## Current drawback, 0..100 (the flipper's; read only).
var power: float:
	get:
		return _drawback.power
## True between a press on the flipper (or a charge key) and its release (read only).
var drawing: bool:
	get:
		return _drawback.drawing
## Where every ball went (counters for the stats panel and the autoplay).
var ledger: PachinkoLedger
## The bonus layer: reels, attackers, tulips (idle on a board without bonus pockets).
var bonus: BonusMachine
## The gold pins (gold_pins.gd): each one a ball puts out adds a ball to the cup.
var gold: GoldPins
## The handle (launch_handle.gd): held, it streams balls at its strength.
var handle := LaunchHandle.new()

var _in_play: Dictionary = {}
var _drawback := FlipperDrawback.new()
var _upkeep := BallUpkeep.new()
var _rng := RandomNumberGenerator.new()
var _step_seconds := 1.0 / 60.0
var _launch_pos := Vector2.ZERO
var _launch_dir := Vector2.RIGHT
var _launch_table: LaunchTable
# The session's counts when the current game started (the game's own are the difference).
var _game_start: PachinkoLedger


## Builds the world for `board`. `rng_seed` makes the nudges repeatable.
func _init(board: BoardLevel, rng_seed: int = 0) -> void:
	_rng.seed = rng_seed
	_drawback.changed.connect(_on_drawback_changed)
	if board == null or not board.is_pachinko() or board.ring_radius <= 0.0:
		# Stay a harmless, empty game: every call is safe and start_game() refuses.
		push_error("PachinkoRules: a pachinko board with a ring is needed")
		level = BoardLevel.new()
		ledger = PachinkoLedger.new(0)
		world = BallWorld.new()
		bonus = BonusMachine.new(level, world, rng_seed)
		gold = GoldPins.new(level, rng_seed)
		return
	level = board
	ledger = PachinkoLedger.new(board.pockets.size() + board.bonus_pockets.size())
	world = BoardWorldFactory.build(board)
	bonus = BonusMachine.new(board, world, rng_seed)
	gold = GoldPins.new(board, rng_seed, bonus)
	_step_seconds = 1.0 / maxf(world.tuning.fixed_hz, 1.0)
	_launch_pos = LaunchRail.launch_position(board)
	_launch_dir = LaunchRail.launch_direction(board)
	_launch_table = LaunchCalibration.table(board)
	world.ball_captured.connect(_on_ball_pocketed)
	world.ball_drained.connect(_on_ball_drained)
	world.ball_entered_zone.connect(_on_ball_entered_zone)
	world.pin_hit.connect(_on_pin_hit)


## Fills the cup with the board's start balls and loads one (false while a game runs).
func start_game() -> bool:
	if state == State.PLAYING or level.ring_radius <= 0.0:
		return false
	_game_start = ledger.copy() as PachinkoLedger
	cup += level.cup_start_balls
	ledger.given += level.cup_start_balls
	gold.light_first_set()
	_set_state(State.PLAYING)
	game_started.emit(cup)
	cup_changed.emit(cup)
	_load_next()
	_check_game_over()
	return true


## The pointer went down on the flipper at `at` (any coordinates, y down): drawback begins.
func press_flipper(at: Vector2) -> bool:
	if state != State.PLAYING:
		return false
	_drawback.press(at)
	return true


## The pointer moved while drawing back: power is how far it went up from the press.
func drag_to(at: Vector2) -> void:
	_drawback.drag_to(at)


## A charge key or button went down: drawback begins at zero.
func begin_charge() -> bool:
	return press_flipper(Vector2.ZERO)


## Adds charge for a held key over `delta` seconds.
func charge(delta: float) -> void:
	_drawback.charge(delta)


## Sets the drawback directly (an analog trigger), 0..100.
func set_power(value: float) -> void:
	_drawback.set_power(value)


## Lets go of the flipper without firing (the game was paused mid-drawback, and the
## release may never arrive): power drops to zero and the next press starts afresh.
func cancel_draw() -> void:
	_drawback.cancel()


## Lets the flipper go. With some power and a loaded ball it fires; returns the new ball's
## id, or -1 when nothing was fired.
func release() -> int:
	if not _drawback.drawing:
		return -1
	var shot_power := _drawback.release()
	if shot_power <= 0.0:
		return -1
	return fire(shot_power)


## Fires the loaded ball with `shot_power` (0..100) and loads the next at once. Returns the
## ball id, or -1 (and nothing happens) when no ball is loaded or the rail is blocked.
func fire(shot_power: float) -> int:
	if state != State.PLAYING or not loaded or rail_blocked():
		return -1
	shot_power = snappedf(shot_power, POWER_STEP)
	var speed := launch_speed(shot_power)
	var id := world.spawn_ball(_launch_pos, _launch_dir * speed, level.ball_radius)
	if id < 0:
		return -1
	loaded = false
	_in_play[id] = true
	ledger.shots += 1
	ball_launched.emit(id, shot_power, speed)
	_load_next()
	return id


## Puts an extra ball in play at `at` moving at `velocity` (tests and tools: a ball dropped
## onto the field). It counts as given, not as a shot. Returns its id, or -1.
func place_ball(at: Vector2, velocity: Vector2 = Vector2.ZERO) -> int:
	var id := world.spawn_ball(at, velocity, level.ball_radius)
	if id >= 0:
		_in_play[id] = true
		ledger.given += 1
	return id


## True while a weak shot is rolling back down the launch rail: the launcher holds its
## ball until the rail is clear, or the two would meet head-on and both roll back.
func rail_blocked() -> bool:
	return RailTraffic.ball_coming_down(level, world.get_positions(), world.get_velocities())


## Launch speed at the bottom of the rail for a power: the one the board's LaunchTable
## says reaches the power's mouth speed (see launch_power.gd).
func launch_speed(shot_power: float) -> float:
	if _launch_table == null:
		return 0.0
	return _launch_table.launch_speed(shot_power)


## Runs the simulation for `delta` seconds of game time; returns the steps taken.
func advance(delta: float) -> int:
	var steps := world.advance(delta)
	_after_steps(steps)
	return steps


## Runs exactly `count` fixed steps as one frame, as `advance` does for a frame that ran
## `count` steps; replays play recorded frames with it.
func run_steps(count: int) -> void:
	for i in count:
		world.step(_step_seconds)
	_after_steps(count)


## Runs exactly one fixed simulation step.
func step() -> void:
	world.step(_step_seconds)
	_after_steps(1)


## Seconds per simulation step.
func step_seconds() -> float:
	return _step_seconds


## Balls in the field or on the rail.
func balls_in_play() -> int:
	return _in_play.size()


## Ids of the balls in play.
func ball_ids() -> Array:
	return _in_play.keys()


## True when cup + loaded + in play + drained + won adds up to every ball given or paid,
## and the world holds exactly the balls the rules think are in play.
func accounting_ok() -> bool:
	var balanced := ledger.balances(cup, 1 if loaded else 0, _in_play.size())
	return balanced and world.ball_count() == _in_play.size()


## Everything the autoplay reports, counted over every game since the rules were made;
## with `this_game` the same figures over the current (or last) game only: what the side
## panel shows, so "play again" starts it from nothing.
func stats(this_game: bool = false) -> Dictionary:
	var game := _game_ledger()
	var out := game.to_dict() if this_game else ledger.to_dict()
	out["cup"] = cup
	out["loaded"] = loaded
	out["in_play"] = _in_play.size()
	out["balls_left"] = cup + (1 if loaded else 0)
	out["game_payouts"] = game.paid
	out["game_shots"] = game.shots
	out["game_hits"] = game.won
	out["accounting_ok"] = accounting_ok()
	out.merge(bonus.counters())
	out.merge(gold.counters())
	return out


# The counts of the current (or last) game: the session's less those at its start.
func _game_ledger() -> PachinkoLedger:
	return (ledger.since(_game_start) if _game_start != null else ledger.copy()) as PachinkoLedger


func _after_steps(steps: int) -> void:
	if steps > 0:
		# a jackpot round's clock waits while nothing is on the board and nothing is shot
		bonus.round_clock_runs = not _in_play.is_empty() or handle.held or drawing
		bonus.advance(steps * _step_seconds)
		gold.advance(steps * _step_seconds)
	if steps > 0 and handle.update(steps * _step_seconds) and fire(handle.shot_power(_rng)) >= 0:
		handle.fired()
	if steps <= 0 or _in_play.is_empty():
		return
	_reconcile()
	var seconds := steps * _step_seconds
	var jammed := _upkeep.jammed(level, world, _in_play.keys(), seconds)
	for id: int in jammed:
		var pocket: int = jammed[id]
		world.remove_ball(id)
		_on_ball_pocketed(id, pocket)
	for id in _upkeep.nudge_resting(world, _in_play.keys(), seconds, _rng):
		ledger.nudges += 1
		ball_nudged.emit(id)


# A ball the world dropped without a signal would break the accounting: count it as
# drained, keep a counter so tests catch it, and move on.
func _reconcile() -> void:
	var gone := BallUpkeep.vanished(world, _in_play.keys())
	for id in gone:
		push_warning("PachinkoRules: ball %d left the world without an event" % id)
		ledger.vanished += 1
		ledger.drained += 1
		_leave_play(id)
	if not gone.is_empty():
		_check_game_over()


func _load_next() -> void:
	if loaded or cup <= 0 or state != State.PLAYING:
		return
	cup -= 1
	loaded = true
	cup_changed.emit(cup)
	ball_loaded.emit()


func _leave_play(id: int) -> void:
	_in_play.erase(id)
	_upkeep.forget(id)


func _check_game_over() -> void:
	if state == State.PLAYING and cup == 0 and not loaded and _in_play.is_empty():
		_drawback.cancel()
		handle.let_go()
		_set_state(State.GAME_OVER)
		game_ended.emit(stats())


func _set_state(new_state: State) -> void:
	if state != new_state:
		state = new_state
		state_changed.emit(state)


func _on_drawback_changed(drawn: float) -> void:
	power_changed.emit(drawn)


func _on_ball_pocketed(ball_id: int, pocket_id: int) -> void:
	if not _in_play.has(ball_id):
		return
	_leave_play(ball_id)
	var payout := 0
	var at := Vector2.ZERO
	if pocket_id >= 0 and pocket_id < level.pockets.size():
		payout = maxi(level.pockets[pocket_id].payout, 0)
		at = level.pockets[pocket_id].position
	elif BonusGeometry.bonus_index(level, pocket_id) >= 0:
		var index := BonusGeometry.bonus_index(level, pocket_id)
		payout = bonus.catch(index)
		at = level.bonus_pockets[index].position
	payout = gold.boosted(payout)
	ledger.record_win(pocket_id, payout)
	cup += payout
	# the win first, so the tray pours these balls before the goal reads the count (trial 8)
	ball_won.emit(ball_id, pocket_id, payout, at)
	cup_changed.emit(cup)
	_load_next()
	_check_game_over()


func _on_ball_drained(ball_id: int) -> void:
	if not _in_play.has(ball_id):
		return
	_leave_play(ball_id)
	ledger.drained += 1
	ball_drained.emit(ball_id)
	_check_game_over()


# A ball in play putting out a lit gold pin adds a ball to the cup (the ledger's gold).
func _on_pin_hit(ball_id: int, pin: int, _speed: float) -> void:
	if _in_play.has(ball_id) and gold.touch(pin):
		ledger.gold += 1
		cup += 1
		cup_changed.emit(cup)
		_load_next()


# Zone 0 is the launch rail's return zone at the bottom of the rail.
func _on_ball_entered_zone(ball_id: int, zone_index: int) -> void:
	if zone_index != 0 or not _in_play.has(ball_id):
		return
	world.remove_ball(ball_id)
	_leave_play(ball_id)
	ledger.returned += 1
	cup += 1
	cup_changed.emit(cup)
	ball_returned.emit(ball_id)
	_load_next()
