# gdlint: disable=max-public-methods
# The contract in scripts/physics/README.md is one façade; its getters are small on purpose.
class_name BallWorld
extends RefCounted
## Fixed-step ball physics in GDScript, with no Node and no built-in physics: circles
## (balls) against pins, capsule walls, a ring border and each other, plus sensors.
##
## Add the shapes through `shapes` (WorldShapes: pins, walls, ring, sensors, windmills), call
## build_grid() (adding later rebuilds lazily), spawn balls, then call advance(delta) every
## frame (or step(dt) directly). Events come out as signals at the end of each step, in the
## order they happened; balls an event removed (captured, drained, fell in a hole) are gone.
##
## A step runs as stages (see step()); the per-ball ones run on `threads` worker threads,
## and any thread count gives bit-identical results. The engine knows shapes, materials and
## sensors, not games: the maze tilt (MazeTilt), the pins' minimum horizontal speed and the
## sensors are set from outside (BoardWorldFactory, the rules).

# Emitted at the end of a step by WorldSignals (so unused here, as the warnings would say).
@warning_ignore_start("unused_signal")
## A ball bounced off a pin (for sound); impact_speed is the normal speed in px/s.
signal pin_hit(ball_id: int, pin_index: int, impact_speed: float)
## A ball bounced off a capsule wall.
signal wall_hit(ball_id: int, wall_index: int, impact_speed: float)
## A ball bounced off the ring border.
signal ring_hit(ball_id: int, impact_speed: float)
## A ball bounced off a windmill's blade (the speed is relative to the moving blade).
signal windmill_hit(ball_id: int, windmill_index: int, impact_speed: float)
## A ball bounced off a petal of gate `gate_index` (the speed is relative to the petal).
signal gate_hit(ball_id: int, gate_index: int, impact_speed: float)
## A ball touched a capturing pin (the pin's tag); it has been removed.
signal ball_captured(ball_id: int, tag: int)
## A ball used up its bounces on the drain arc (or rolled there); it has been removed.
signal ball_drained(ball_id: int)
## A ball's centre came within a hole's radius; it has been removed.
signal ball_fell_in_hole(ball_id: int, hole_index: int)
## A ball's centre moved inside a goal's radius (the ball stays).
signal ball_reached_goal(ball_id: int, goal_index: int)
## A ball's centre moved back out of a goal's radius.
signal ball_left_goal(ball_id: int, goal_index: int)
## A ball's centre moved inside a zone's radius (the ball stays).
signal ball_entered_zone(ball_id: int, zone_index: int)
@warning_ignore_restore("unused_signal")

## The physics behaviour: bumped whenever the same inputs roll the balls differently, so
## replays of older runs are refused by name (Replay.PHYSICS_VERSION); each version's change
## is listed in scripts/physics/README.md ("Physics versions").
const PHYSICS_VERSION := 4
## advance() runs at most this many steps a call and drops the backlog (a hitch slows the
## game, never freezes it); 30 (0.25 s at 120 Hz) keeps real time down to 4 frames a second.
const MAX_STEPS_PER_ADVANCE := 30
## Goals and zones are tracked per ball in one int bit mask each: at most this many of each.
const MAX_SENSORS := StaticShapes.MAX_SENSORS
## Balls smaller than this still get a grid sized for it (px).
const MIN_GRID_BALL_RADIUS := 5.0

## The constants in use (restitution, caps, fixed_hz, ...).
var tuning: PhysicsTuning:
	set(value):
		tuning = value
		if shapes != null:
			shapes.tuning = value
## Gravity in px/s²; may change every frame (the maze rules tilt it).
var gravity: Vector2
## Rolling friction per axis in px/s² (only slows, never reverses); may change every frame.
var rolling_friction: Vector2
## Steps run so far.
var step_count := 0
## Called with the step's length at the start of every step when set (a rule's own force,
## the maze's GoalDip); worlds without it step exactly as before.
var before_step := Callable()
## False tests every ball against every pin (the benchmark's "no zoning" baseline).
var use_zoning := true:
	set(value):
		use_zoning = value
		_geo.shapes.dirty = true
## False lets balls pass through each other (no ball-ball contacts): each ball then moves
## as if alone, so one world can run many independent shots at once (the play analysis).
var ball_contacts := true
## Worker threads the per-ball stages may use (default: every core; 1 = this thread only);
## any value gives bit-identical results.
var threads: int = OS.get_processor_count():
	set(value):
		threads = maxi(value, 1)
		_lanes.threads = threads
## True times each stage of every step (see stage_times()); off by default.
var profile_stages := false:
	set(value):
		profile_stages = value
		_clock.enabled = value
		_clock.reset()
## With profile_stages: count this thread's CPU time rather than wall time (Linux).
var profile_cpu_time := false:
	set(value):
		profile_cpu_time = value
		_clock.cpu_time = value

## The door to the world's shapes (`world.shapes.add_pin(...)`): see WorldShapes.
var shapes: WorldShapes

var _geo := StaticGeometry.new()
var _wheels := Windmills.new()
var _gates := Gates.new()
var _balls := BallStore.new()
var _lanes := BallLanes.new()
var _pairs := BallPairs.new()
var _motion := MotionStage.new(_balls, _geo, _wheels, _lanes)
var _clock := StageClock.new()
## This step's events (see BallEvents), gathered from the lanes in lane order.
var _events := PackedInt32Array()
var _event_speed := PackedFloat32Array()
var _accumulator := 0.0
## Gravity and friction of the last step: a change has each sleeper check its footing.
var _last_gravity := Vector2.ZERO
var _last_friction := Vector2.ZERO
## step_count when every ball was last woken: none sleeps for tuning.sleep_time after it.
var _woken_at_step := 0
## True from the start of step() until its signals are out: a handler that steps the world
## from inside them is refused (the step would run inside another, half done).
var _stepping := false


func _init(p_tuning: PhysicsTuning = null) -> void:
	tuning = p_tuning if p_tuning != null else PhysicsTuning.new()
	shapes = WorldShapes.new(_geo, _wheels, _gates, tuning)
	_lanes.threads = threads
	gravity = tuning.gravity
	rolling_friction = Vector2(tuning.rolling_friction, tuning.rolling_friction)


## Bins the static shapes and the windmills into the grid. Adding shapes or bigger balls
## later rebuilds it.
func build_grid() -> void:
	shapes.bin(maxf(_balls.max_radius, MIN_GRID_BALL_RADIUS), use_zoning)
	_balls.keys_valid = false
	_balls.wake_all()


## Spawns a ball; returns its stable id, or -1 with an error for a radius <= 0 or
## non-finite input.
func spawn_ball(pos: Vector2, vel: Vector2, radius: float) -> int:
	var problem := WorldInputChecks.spawn_problem(pos, vel, radius)
	if not problem.is_empty():
		push_error(problem)
		return -1
	if radius > _geo.built_ball_radius:
		_geo.shapes.dirty = true
	return _balls.add(pos, vel, radius)


## Removes a ball (no signal). Unknown ids are ignored.
func remove_ball(id: int) -> void:
	_balls.remove(PackedInt32Array([id]))


## remove_ball() on each of `ids`, with one compaction for all (no signal, unknown ignored).
func remove_balls(ids: PackedInt32Array) -> void:
	_balls.remove(ids)


## Removes every ball.
func clear_balls() -> void:
	_balls.remove(_balls.ids)


func has_ball(id: int) -> bool:
	return _balls.find(id) >= 0


func ball_count() -> int:
	return _balls.ids.size()


## Position of a ball, or Vector2.ZERO for an unknown id.
func get_ball_position(id: int) -> Vector2:
	var i: int = _balls.find(id)
	return _balls.pos[i] if i >= 0 else Vector2.ZERO


## Moves a ball (teleport: no sweep). Used by rules to reset or place balls.
func set_ball_position(id: int, pos: Vector2) -> void:
	var i: int = _balls.find(id)
	if i >= 0 and pos.is_finite():
		_balls.pos[i] = pos
		_balls.keys_valid = false
		_balls.rest[i] = 0.0
		# Balls it was holding up (or that it now lands in) must move again.
		_balls.wake_all()


## Velocity of a ball, or Vector2.ZERO for an unknown id.
func get_ball_velocity(id: int) -> Vector2:
	var i: int = _balls.find(id)
	return _balls.vel[i] if i >= 0 else Vector2.ZERO


## Sets a ball's velocity and wakes every ball (a ball set moving may run into sleepers);
## with `wake_others` false, that ball alone: a rule's nudge in place every step (GoalDip).
func set_ball_velocity(id: int, v: Vector2, wake_others := true) -> void:
	var i: int = _balls.find(id)
	if i < 0:
		return
	if not v.is_finite():
		push_error("BallWorld.set_ball_velocity: velocity must be finite (got %s)" % v)
		return
	_balls.vel[i] = v
	_balls.rest[i] = 0.0
	if wake_others:
		_balls.wake_all()
	else:
		_balls.asleep[i] = 0


## Radius of a ball, or 0 for an unknown id.
func get_ball_radius(id: int) -> float:
	var i: int = _balls.find(id)
	return _balls.radius[i] if i >= 0 else 0.0


## True while the ball sleeps (it rested for tuning.sleep_time and nothing has woken it).
func is_ball_asleep(id: int) -> bool:
	var i: int = _balls.find(id)
	return i >= 0 and _balls.asleep[i] != 0


## Seconds the ball's speed has stayed below tuning.rest_speed (0 for an unknown id).
func get_ball_rest_time(id: int) -> float:
	var i: int = _balls.find(id)
	return _balls.rest[i] if i >= 0 else 0.0


## Positions of all balls, dense, in the same order as get_radii() and get_ids() (copies:
## packed arrays are shared by reference, and the world's own must not change under it).
func get_positions() -> PackedVector2Array:
	return _balls.handed_out(&"pos", _balls.pos.duplicate())


func get_velocities() -> PackedVector2Array:
	return _balls.handed_out(&"vel", _balls.vel.duplicate())


func get_radii() -> PackedFloat32Array:
	return _balls.handed_out(&"radius", _balls.radius.duplicate())


func get_ids() -> PackedInt32Array:
	return _balls.handed_out(&"ids", _balls.ids.duplicate())


## Turns path recording on or off (see take_step_paths()); off by default, for checks only.
func set_path_recording(on: bool) -> void:
	_balls.tracing = on
	_balls.take_paths()


## The points each ball passed through between its substeps since the last call, for an
## outside check that follows the real path rather than the straight line between two
## frames: {"slots": PackedInt32Array, "points": PackedVector2Array}, ordered by slot (the
## index in get_positions() before the step's removals) and then by time. Clears them.
func take_step_paths() -> Dictionary:
	return _balls.take_paths()


## Runs one step of `dt` seconds, then emits its events in order. The stages: integrate
## (gravity), broad phase (touching ball pairs), ball-ball solve, motion (per ball: a
## sleeper stays or wakes; an awake ball gets friction and the speed cap, then substeps with
## the narrow phase per shape kind and one contact response, then rest, sleep and sensors),
## events. A handler of one of those events that calls step() is refused with an error.
func step(dt: float) -> void:
	if _stepping:
		var problem: String = "BallWorld.step: called from a handler of this world's own signal"
		push_error(problem + " (the step is not over yet); step again after the signal returns")
		return
	if not _inputs_ok(dt):
		return
	if before_step.is_valid():
		before_step.call(dt)
	_stepping = true
	if _geo.shapes.dirty or _balls.max_radius > _geo.built_ball_radius:
		build_grid()
	# A gravity change wakes only the sleepers it would move (BallSleep checks each).
	var turned: bool = gravity != _last_gravity or rolling_friction != _last_friction
	_last_gravity = gravity
	_last_friction = rolling_friction
	_clock.start()
	# Integrate: this step's gravity, as one native translate of every velocity. Sleepers
	# get it too (the sleep stage zeroes them again); rolling friction and the speed cap
	# come in the motion stage, as each ball is read.
	_balls.vel = Transform2D(Vector2.RIGHT, Vector2.DOWN, gravity * dt) * _balls.vel
	_clock.lap(StageClock.Stage.INTEGRATE)
	_ball_contacts_stages(dt)
	var t: PhysicsTuning = tuning
	if _balls.woken:
		_balls.woken = false
		_woken_at_step = step_count
	var may_sleep: bool = (step_count - _woken_at_step) * dt >= t.sleep_time
	WorldSignals.hear_hits(self, _motion.hits_heard)
	if _gates.count() > 0:
		_gates.begin_step(_wheels, dt, tuning.max_speed)
	_motion.run(tuning, gravity, rolling_friction, dt, turned, may_sleep)
	_clock.lap(StageClock.Stage.MOTION)
	_events.append_array(_motion.events)
	_event_speed.append_array(_motion.event_speed)
	if _wheels.count() > 0:
		_wheels.advance(dt, _motion.wheel_push_index, _motion.wheel_push, tuning.max_speed)
		_gates.end_step(_wheels)
	_balls.compact()
	step_count += 1
	_emit_events()
	_stepping = false
	_clock.lap(StageClock.Stage.EVENTS, true)


## Broad phase and ball-ball solve (see BallPairs): the broad phase's lanes answer the even
## stripes as they list them, then a second hand-off answers the odd ones. The same
## schedule whether or not the stages are timed: the clock laps at the same two points.
func _ball_contacts_stages(dt: float) -> void:
	var t: PhysicsTuning = tuning
	_pairs.begin(_balls, t.ball_restitution, t.bounce_threshold, t.rest_speed, gravity * dt)
	if ball_contacts:
		_pairs.find(_balls, _geo, _lanes, true)
	else:
		# No broad phase: the motion stage skips the keys, and they are binned again when
		# ball contacts come back on.
		_balls.keys_valid = false
	_clock.lap(StageClock.Stage.FIND_AND_SOLVE_EVEN)
	if ball_contacts:
		_pairs.solve_stripes(_lanes, 1)
	_pairs.finish(_balls)
	_clock.lap(StageClock.Stage.SOLVE_ODD)


## Feeds the accumulator and runs every whole step of 1 / tuning.fixed_hz it holds (at most
## MAX_STEPS_PER_ADVANCE). Returns how many steps ran.
func advance(delta: float) -> int:
	if not is_finite(delta) or delta < 0.0:
		push_error("BallWorld.advance: delta must be finite and >= 0 (got %s)" % delta)
		return 0
	var h: float = 1.0 / maxf(tuning.fixed_hz, 1.0)
	_accumulator += delta
	var ran := 0
	while _accumulator >= h and ran < MAX_STEPS_PER_ADVANCE:
		step(h)
		_accumulator -= h
		ran += 1
	if ran == MAX_STEPS_PER_ADVANCE and _accumulator >= h:
		_accumulator = 0.0
	return ran


## Average wall time per step of each stage in µs since profile_stages was turned on, by
## stage name (StageClock.NAMES: integrate, find_and_solve_even, solve_odd, motion,
## events) plus "total".
func stage_times() -> Dictionary:
	return _clock.per_step()


## A hash of the whole dynamic state: equal hashes after N steps mean identical runs.
func state_hash() -> int:
	var b: BallStore = _balls
	if _gates.count() > 0:
		var gates: Array = [_gates.openness, _gates.target, _gates.phase_time]
		return hash([step_count, b.ids, b.pos, b.vel, b.rest, _wheels.angle, _wheels.omega, gates])
	if _wheels.count() > 0:
		return hash([step_count, b.ids, b.pos, b.vel, b.rest, _wheels.angle, _wheels.omega])
	return hash([step_count, _balls.ids, _balls.pos, _balls.vel, _balls.rest])


# Emits this step's queued events as the signals above, in the order they happened.
func _emit_events() -> void:
	var ev: PackedInt32Array = _events
	if ev.is_empty():
		return
	var evs: PackedFloat32Array = _event_speed
	# Fresh buffers first: a handler may add or remove balls (it may not step: see step()).
	_events = PackedInt32Array()
	_event_speed = PackedFloat32Array()
	WorldSignals.emit(self, shapes, ev, evs)


## Refuses a bad dt; replaces non-finite gravity or friction with zero. False to skip.
func _inputs_ok(dt: float) -> bool:
	var problem := WorldInputChecks.step_problem(dt)
	if not problem.is_empty():
		push_error(problem)
		return false
	gravity = WorldInputChecks.finite_or_zero(gravity, "gravity")
	rolling_friction = WorldInputChecks.finite_or_zero(rolling_friction, "rolling_friction")
	return true
