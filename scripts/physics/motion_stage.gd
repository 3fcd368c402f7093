class_name MotionStage
extends RefCounted
## The motion stage over every ball: per lane, the sleepers first (BallSleep: each stays or
## wakes), then a BallMover moves the awake ones; run on the world's lanes (worker
## threads), then their events and path points gathered in lane order, which is ball order,
## so any number of lanes gives the same result. Internal to scripts/physics.
##
## One mover per worker thread, not per lane: it takes the step's state (BallMover.begin)
## on its thread, once, and notes where each lane's events and points start and end in its
## buffers, so the gathering can put them in lane order.

## Per lane in _lane_spans: where its events, path points and wheel pushes start and end.
const SPANS := 6

## This step's events (see BallEvents) and their speeds, in ball order.
var events := PackedInt32Array()
var event_speed := PackedFloat32Array()
## 1 for each hit event kind that is queued (BallEvents.Kind.PIN_HIT, WALL_HIT, RING_HIT).
var hits_heard := PackedByteArray([1, 1, 1, 1])
## This step's pushes on free windmills (wheel index, change of angular speed), in ball order.
var wheel_push_index := PackedInt32Array()
var wheel_push := PackedFloat64Array()

var _balls: BallStore
var _geo: StaticGeometry
var _wheels: Windmills
var _lanes: BallLanes
## One mover per worker; _begun[w] is 1 once mover w has taken this step's state.
var _movers: Array[BallMover] = []
var _begun := PackedByteArray()
## Per lane: the worker that ran it, and where its events (count of speeds), its path
## points and its wheel pushes start and end in that worker's mover (SPANS numbers).
var _lane_worker := PackedInt32Array()
var _lane_spans := PackedInt32Array()
var _tuning: PhysicsTuning
var _may_sleep := true
# This step's sleep inputs (see BallSleep.settle); _any_asleep false skips it.
var _any_asleep := false
var _gravity := Vector2.ZERO
var _friction := Vector2.ZERO
var _dt := 0.0
var _turned := false


func _init(balls: BallStore, geo: StaticGeometry, wheels: Windmills, lanes: BallLanes) -> void:
	_balls = balls
	_geo = geo
	_wheels = wheels
	_lanes = lanes


## Settles the sleepers and moves every awake ball through one step of `dt` s (see
## BallSleep and BallMover); `turned` says gravity or friction changed since the last
## step, `may_sleep` is false just after a wake-up. Fills `events` and `event_speed`, and
## the store's path points.
func run(
	tuning: PhysicsTuning,
	gravity: Vector2,
	friction: Vector2,
	dt: float,
	turned: bool,
	may_sleep: bool
) -> void:
	var n: int = _balls.ids.size()
	_any_asleep = _balls.asleep.count(0) != n
	_gravity = gravity
	_friction = friction
	_dt = dt
	_turned = turned
	_tuning = tuning
	_may_sleep = may_sleep
	var lanes: int = _lanes.lanes_for(n)
	var workers: int = _lanes.workers_for(n)
	while _movers.size() < workers:
		_movers.append(BallMover.new())
	_begun.resize(workers)
	_begun.fill(0)
	_lane_worker.resize(lanes)
	_lane_spans.resize(lanes * SPANS)
	# The lanes write the store's arrays side by side: each already has a buffer of its own
	# (the solve's begin() saw to it this step, see BallStore.own_buffers(), and no array
	# has been handed out since: the step's signals come after the motion).
	_lanes.run_by_worker(_move_lane, n)
	_gather(lanes)


## This step's events, path points and wheel pushes from the movers, in lane order.
func _gather(lanes: int) -> void:
	events.resize(0)
	event_speed.resize(0)
	wheel_push_index.resize(0)
	wheel_push.resize(0)
	if lanes == 1:
		events = _movers[0].events.duplicate()
		event_speed = _movers[0].event_speed.duplicate()
		if not _movers[0].wheel_push.is_empty():
			wheel_push_index = _movers[0].wheel_push_index.duplicate()
			wheel_push = _movers[0].wheel_push.duplicate()
		if _balls.tracing:
			_balls.trace_ball.append_array(_movers[0].trace_ball)
			_balls.trace_pos.append_array(_movers[0].trace_pos)
		return
	for lane: int in lanes:
		var mover: BallMover = _movers[_lane_worker[lane]]
		var ev0: int = _lane_spans[lane * SPANS]
		var ev1: int = _lane_spans[lane * SPANS + 1]
		if ev1 > ev0:
			events.append_array(mover.events.slice(ev0 * 3, ev1 * 3))
			event_speed.append_array(mover.event_speed.slice(ev0, ev1))
		var tr0: int = _lane_spans[lane * SPANS + 2]
		var tr1: int = _lane_spans[lane * SPANS + 3]
		if _balls.tracing and tr1 > tr0:
			_balls.trace_ball.append_array(mover.trace_ball.slice(tr0, tr1))
			_balls.trace_pos.append_array(mover.trace_pos.slice(tr0, tr1))
		var wp0: int = _lane_spans[lane * SPANS + 4]
		var wp1: int = _lane_spans[lane * SPANS + 5]
		if wp1 > wp0:
			wheel_push_index.append_array(mover.wheel_push_index.slice(wp0, wp1))
			wheel_push.append_array(mover.wheel_push.slice(wp0, wp1))


## One lane on worker `worker`: its sleepers, then its awake balls.
func _move_lane(worker: int, lane: int, from: int, to: int) -> void:
	var mover: BallMover = _movers[worker]
	if _begun[worker] == 0:
		_begun[worker] = 1
		mover.begin(
			_balls, _geo, _wheels, _tuning, _gravity, _friction, _dt, _may_sleep, hits_heard
		)
	_lane_worker[lane] = worker
	var at: int = lane * SPANS
	_lane_spans[at] = mover.event_speed.size()
	_lane_spans[at + 2] = mover.trace_pos.size()
	_lane_spans[at + 4] = mover.wheel_push.size()
	if _any_asleep:
		BallSleep.settle(_balls, from, to, _gravity, _friction, _dt, _turned)
	mover.move_range(from, to)
	_lane_spans[at + 1] = mover.event_speed.size()
	_lane_spans[at + 3] = mover.trace_pos.size()
	_lane_spans[at + 5] = mover.wheel_push.size()
