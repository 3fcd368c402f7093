class_name MazeSteering
extends RefCounted
## The autoplay's continuous steering: tilts that make balls follow their paths (MazeNav),
## centre a pack in the goal, or lead the ball nearest the goal. Used by MazePilot.

## Smallest tilt that still moves a resting ball, with a margin, degrees: past the felt near
## level (maze rules 5), under which a ball at rest needs about 1.1° (0.6° before it).
const MIN_NUDGE_DEG := MazeTilt.FELT_GONE_DEG + 0.1

## Degrees of tilt per px/s of velocity error.
var gain := 0.2
## How far ahead along the path a ball aims, in px.
var lookahead := 12.0
## Cruising speed as a share of the board's speed cap.
var cruise := 0.85
## The board's speed cap, px/s.
var max_speed := 93.75

var _nav: MazeNav
var _level: BoardLevel


func _init(level: BoardLevel, nav: MazeNav, speed_cap: float) -> void:
	_level = level
	_nav = nav
	max_speed = speed_cap


## Each ball asks for the velocity that follows its own path; the tilt serves their average
## (packed balls want nearly the same thing, and a ball a cell behind is led round the
## corner the others took).
func follow_paths(positions: PackedVector2Array, velocities: PackedVector2Array) -> Vector2:
	var tilt := Vector2.ZERO
	for i in positions.size():
		var aim := _nav.carrot(positions[i], lookahead)
		tilt += velocity_tilt(aim, positions[i], velocities[i], cruise)
	return TiltInput.clamp_tilt(tilt / float(maxi(positions.size(), 1)))


## In the goal: slides the whole pack so the middle of its bounding box sits on the goal's
## centre. Every axis that still has to move gets at least MIN_NUDGE_DEG, enough to beat
## rolling friction (which holds a ball still below about 0.6°).
func centre_pack(positions: PackedVector2Array, velocities: PackedVector2Array) -> Vector2:
	var lo := positions[0]
	var hi := positions[0]
	var mean_v := Vector2.ZERO
	for i in positions.size():
		lo = lo.min(positions[i])
		hi = hi.max(positions[i])
		mean_v += velocities[i]
	mean_v /= float(positions.size())
	var to := _level.goal_center - (lo + hi) * 0.5
	var want := (to * 3.0).limit_length(max_speed * 0.4)
	var tilt := (want - mean_v) * gain
	for axis in 2:
		if absf(to[axis]) > 1.5 and absf(tilt[axis]) < MIN_NUDGE_DEG:
			tilt[axis] = signf(to[axis]) * MIN_NUDGE_DEG
	return TiltInput.clamp_tilt(tilt)


## Steers the ball nearest the goal that is not in yet; balls already in pull gently back.
func lead(positions: PackedVector2Array, velocities: PackedVector2Array) -> Vector2:
	var leader := -1
	var leader_distance := INF
	var hold := Vector2.ZERO
	for i in positions.size():
		if positions[i].distance_to(_level.goal_center) < _level.goal_radius - 2.0:
			hold += velocity_tilt(_level.goal_center, positions[i], velocities[i], 0.4)
			continue
		var d := _nav.distance_at(positions[i])
		if d < leader_distance:
			leader_distance = d
			leader = i
	var tilt := hold * 0.25
	if leader >= 0:
		var target := _nav.carrot(positions[leader], lookahead)
		tilt += velocity_tilt(target, positions[leader], velocities[leader], cruise)
	return TiltInput.clamp_tilt(tilt)


## The tilt that turns velocity `v` toward moving at `share` of the cap toward `target`,
## slowing down as the target nears.
func velocity_tilt(target: Vector2, p: Vector2, v: Vector2, share: float) -> Vector2:
	var to := target - p
	var speed := minf(max_speed * share, to.length() * 3.0)
	var want := to.normalized() * speed if to.length() > 0.01 else Vector2.ZERO
	return (want - v) * gain


## Largest distance of a ball from the balls' centre, px.
static func spread(positions: PackedVector2Array) -> float:
	var centre := Vector2.ZERO
	for p in positions:
		centre += p
	centre /= float(maxi(positions.size(), 1))
	var widest := 0.0
	for p in positions:
		widest = maxf(widest, p.distance_to(centre))
	return widest
