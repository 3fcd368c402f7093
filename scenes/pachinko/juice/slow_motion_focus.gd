class_name SlowMotionFocus
extends Node2D
## Shows the slow motion: while the clock is slow the board darkens outside a spotlight on
## the ball about to drop in, and a thin ring circles that ball, both as deep as the clock
## is slow. Follows SlowMotion; one canvas item, asleep at full speed.

## Board pixels of the spotlight's clear middle, and of its soft edge.
const SPOT_RADIUS := 46.0
const SPOT_EDGE := 40.0
## How dark the board gets outside the spotlight at the slowest.
const DIM := 0.55
## Reach of the dimmed area beyond the spotlight (covers any board).
const DIM_REACH := 1400.0
const RING := Color(1.0, 0.92, 0.6)

var _slow: SlowMotion
var _world: BallWorld
var _at := Vector2.ZERO


## Follows `slow`'s slow motion over the balls of `world`.
func bind(slow: SlowMotion, world: BallWorld) -> void:
	_slow = slow
	_world = world
	if not slow.started.is_connected(_on_started):
		slow.started.connect(_on_started)
	set_process(slow.is_slow())
	queue_redraw()


## How deep the focus shows now, 0 (full speed) to 1 (slowest).
func depth() -> float:
	if _slow == null or not _slow.is_slow():
		return 0.0
	var slowest := 1.0 - SlowMotion.SLOW_SCALE
	return clampf((1.0 - _slow.time_scale()) / slowest, 0.0, 1.0)


func _on_started(_ball: int) -> void:
	set_process(true)


func _process(_delta: float) -> void:
	var ball := _slow.followed_ball() if _slow != null else -1
	if ball >= 0 and _world != null and _world.has_ball(ball):
		_at = _world.get_ball_position(ball)
	queue_redraw()
	if depth() <= 0.0:
		set_process(false)


func _draw() -> void:
	var amount := depth()
	if amount <= 0.0:
		return
	# The dark outside the spot: a soft edge from clear to dark, then dark out to DIM_REACH.
	var shade := Color(0.0, 0.0, 0.05, DIM * amount)
	var outer := SPOT_RADIUS + SPOT_EDGE
	_draw_ring(SPOT_RADIUS, outer, Color(shade, 0.0), shade)
	_draw_ring(outer, outer + DIM_REACH, shade, shade)
	draw_arc(_at, 12.0, 0.0, TAU, 32, Color(RING, 0.85 * amount), 2.0, true)


# A ring around the spot from `inner` to `outer` px, shaded from `inside` to `outside`.
func _draw_ring(inner: float, outer: float, inside: Color, outside: Color) -> void:
	var segments := 48
	for i in segments:
		var a := Vector2.from_angle(TAU * i / segments)
		var b := Vector2.from_angle(TAU * (i + 1) / segments)
		var quad := PackedVector2Array(
			[_at + a * inner, _at + b * inner, _at + b * outer, _at + a * outer]
		)
		draw_polygon(quad, PackedColorArray([inside, inside, outside, outside]))
