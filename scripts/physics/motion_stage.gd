extends RefCounted
## The motion stage over every ball: per lane, the sleepers first (BallSleep: each stays or
## wakes), then one BallMover moves the awake ones; run on the world's lanes (worker
## threads), then their events and path points gathered in lane order, which is ball order,
## so any number of lanes gives the same result. Internal to scripts/physics.

const BallStore := preload("res://scripts/physics/ball_store.gd")
const StaticGeometry := preload("res://scripts/physics/static_geometry.gd")
const BallLanes := preload("res://scripts/physics/ball_lanes.gd")
const BallMover := preload("res://scripts/physics/ball_mover.gd")
const BallSleep := preload("res://scripts/physics/ball_sleep.gd")

## This step's events (see BallEvents) and their speeds, in ball order.
var events := PackedInt32Array()
var event_speed := PackedFloat32Array()
## 1 for each hit event kind that is queued (BallEvents.Kind.PIN_HIT, WALL_HIT, RING_HIT).
var hits_heard := PackedByteArray([1, 1, 1])

var _balls: BallStore
var _geo: StaticGeometry
var _lanes: BallLanes
## One mover per lane.
var _movers: Array[BallMover] = []
# This step's sleep inputs (see BallSleep.settle); _any_asleep false skips it.
var _any_asleep := false
var _gravity := Vector2.ZERO
var _friction := Vector2.ZERO
var _dt := 0.0
var _turned := false


func _init(balls: BallStore, geo: StaticGeometry, lanes: BallLanes) -> void:
	_balls = balls
	_geo = geo
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
	var lanes: int = _lanes.lanes_for(n)
	while _movers.size() < lanes:
		_movers.append(BallMover.new())
	if lanes > 1:
		_balls.own_buffers()
	for lane: int in lanes:
		_movers[lane].begin(_balls, _geo, tuning, gravity, friction, dt, may_sleep, hits_heard)
	_lanes.run(_move_lane, n)
	events.resize(0)
	event_speed.resize(0)
	for lane: int in lanes:
		var mover: BallMover = _movers[lane]
		events.append_array(mover.events)
		event_speed.append_array(mover.event_speed)
		if _balls.tracing:
			_balls.trace_ball.append_array(mover.trace_ball)
			_balls.trace_pos.append_array(mover.trace_pos)


func _move_lane(lane: int, from: int, to: int) -> void:
	if _any_asleep:
		BallSleep.settle(_balls, from, to, _gravity, _friction, _dt, _turned)
	_movers[lane].move_range(from, to)
