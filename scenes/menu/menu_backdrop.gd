class_name MenuBackdrop
extends Control
## The menus' animated background: a deep blue gradient, a lattice of brass pins and a few
## silver balls drifting down through it (not on a screen that sets `falling_balls` off).
## Purely decorative; it never takes input.

const PIN_SPACING := 64.0
const PIN_RADIUS := 3.5
const BALL_COUNT := 9
const BALL_RADIUS := 9.0
const TOP_COLOR := Color(0.05, 0.07, 0.14)
const BOTTOM_COLOR := Color(0.11, 0.08, 0.17)
const PIN_COLOR := Color(0.85, 0.66, 0.3, 0.35)
const BALL_COLOR := Color(0.82, 0.86, 0.94, 0.55)

## Balls drift down through the pins. The level select turns them off: a play trial saw
## them fall between the level cards, which read as balls loose on the list.
@export var falling_balls := true

var _time := 0.0
var _rng := RandomNumberGenerator.new()
var _balls: Array[Vector3] = []  # x, y, fall speed


func _ready() -> void:
	mouse_filter = Control.MOUSE_FILTER_IGNORE
	_rng.seed = 7
	if not falling_balls:
		set_process(false)  # the pins and the gradient stand still: drawn once
		return
	for i in BALL_COUNT:
		_balls.append(Vector3(_rng.randf(), _rng.randf(), _rng.randf_range(40.0, 90.0)))


## How many balls fall through the pins (none where `falling_balls` is off).
func ball_count() -> int:
	return _balls.size()


func _process(delta: float) -> void:
	_time += delta
	for i in _balls.size():
		var ball := _balls[i]
		ball.y += ball.z * delta / maxf(size.y, 1.0)
		if ball.y > 1.05:
			ball = Vector3(_rng.randf(), -0.05, _rng.randf_range(40.0, 90.0))
		_balls[i] = ball
	queue_redraw()


func _draw() -> void:
	var colors := PackedColorArray([TOP_COLOR, TOP_COLOR, BOTTOM_COLOR, BOTTOM_COLOR])
	var corners := PackedVector2Array(
		[Vector2.ZERO, Vector2(size.x, 0.0), size, Vector2(0.0, size.y)]
	)
	draw_polygon(corners, colors)
	var row := 0
	var y := PIN_SPACING * 0.5
	while y < size.y:
		var x := PIN_SPACING * (0.5 if row % 2 == 0 else 1.0)
		while x < size.x:
			draw_circle(Vector2(x, y), PIN_RADIUS, PIN_COLOR)
			x += PIN_SPACING
		y += PIN_SPACING * 0.866
		row += 1
	if not falling_balls:
		return
	for ball in _balls:
		var sway := sin(_time * 1.3 + ball.z) * 18.0
		var centre := Vector2(ball.x * size.x + sway, ball.y * size.y)
		draw_circle(centre, BALL_RADIUS, BALL_COLOR)
		draw_circle(centre + Vector2(-3.0, -3.0), BALL_RADIUS * 0.35, Color(1, 1, 1, 0.5))
