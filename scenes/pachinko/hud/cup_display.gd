extends Control
## The ball cup: a chrome tray heaped with balls (more balls, a bigger heap) and the count
## written large on its front. Paid balls pour in from above one after another and the
## count bounces as they land.

const BallLayer := preload("res://scenes/pachinko/board/ball_layer.gd")
const MAX_HEAP := 40
const TRAY := Color("b9bfcc")
const TRAY_DARK := Color("4b5064")
## The font size of "balls in the cup" under the count.
const LABEL_FONT_SIZE := 15

## Most falling balls shown for one payout (a big one still pours for a moment).
const MAX_POUR := 14
## Seconds between two poured balls, and the fall's acceleration (px/s²).
const POUR_GAP := 0.07
const POUR_GRAVITY := 1500.0

var _count := 0
var _bump := 0.0
var _ball: Texture2D
## Balls falling into the cup: x, y, speed and seconds still to wait, per ball.
var _falling: Array[Vector4] = []


## Shows `balls` balls; a rise bounces the number.
func set_count(balls: int) -> void:
	if balls > _count:
		_bump = 1.0
		set_process(true)
	_count = balls
	queue_redraw()


## Pours `balls` paid balls into the cup (an animation; the count is already set).
func pour(balls: int) -> void:
	var shown := mini(balls, MAX_POUR)
	for i in shown:
		var x := size.x * 0.5 + (float(i % 5) - 2.0) * 14.0
		_falling.append(Vector4(x, -12.0, 0.0, POUR_GAP * i))
	if shown > 0:
		set_process(true)


## Balls still falling into the cup.
func pouring() -> int:
	return _falling.size()


## The count shown.
func count() -> int:
	return _count


func _ready() -> void:
	_ball = BallLayer.make_ball_texture(32)
	custom_minimum_size = Vector2(300, 170)
	set_process(false)


func _process(delta: float) -> void:
	_bump = maxf(_bump - delta * 3.0, 0.0)
	var landing := size.y * 0.45
	var still: Array[Vector4] = []
	for ball in _falling:
		if ball.w > 0.0:
			ball.w -= delta
		else:
			ball.z += POUR_GRAVITY * delta
			ball.y += ball.z * delta
		if ball.y < landing:
			still.append(ball)
		else:
			_bump = 1.0  # each landing ball bounces the count
	_falling = still
	queue_redraw()
	if _bump <= 0.0 and _falling.is_empty():
		set_process(false)


func _draw() -> void:
	var w := size.x
	var h := size.y
	var tray_top := h * 0.45
	var rim := Rect2(Vector2(w * 0.08, tray_top), Vector2(w * 0.84, h * 0.5))
	# The heap: rows of balls, narrower towards the top.
	var shown := mini(_count, MAX_HEAP)
	var r := 9.0
	var row := 0
	var placed := 0
	while placed < shown:
		var per_row := maxi(12 - row * 2, 3)
		var y := tray_top - r * 0.5 - row * r * 1.6
		var row_width := per_row * r * 2.0
		for i in per_row:
			if placed >= shown:
				break
			var x := w * 0.5 - row_width * 0.5 + r + i * r * 2.0 + (row % 2) * r * 0.5
			draw_texture_rect(
				_ball, Rect2(Vector2(x, y) - Vector2(r, r), Vector2(r, r) * 2.0), false
			)
			placed += 1
		row += 1
	for ball in _falling:
		if ball.w <= 0.0:
			var at := Vector2(ball.x, ball.y)
			draw_texture_rect(_ball, Rect2(at - Vector2(r, r), Vector2(r, r) * 2.0), false)
	# The tray in front of the heap.
	var tray := PackedVector2Array(
		[
			rim.position,
			rim.position + Vector2(rim.size.x, 0),
			rim.position + Vector2(rim.size.x * 0.9, rim.size.y),
			rim.position + Vector2(rim.size.x * 0.1, rim.size.y),
		]
	)
	draw_colored_polygon(tray, TRAY_DARK)
	var face := PackedVector2Array()
	for p in tray:
		face.append(p.lerp(rim.get_center(), 0.08))
	draw_colored_polygon(face, TRAY)
	draw_line(tray[0], tray[1], Color.WHITE, 3.0, true)
	var font := get_theme_default_font()
	var font_size := int(40 + 14 * _bump)
	var text := str(_count)
	var tw := font.get_string_size(text, HORIZONTAL_ALIGNMENT_LEFT, -1, font_size).x
	var base := Vector2(w * 0.5 - tw * 0.5, rim.position.y + rim.size.y * 0.5 + font_size * 0.35)
	draw_string_outline(font, base, text, HORIZONTAL_ALIGNMENT_LEFT, -1, font_size, 6, TRAY_DARK)
	draw_string(font, base, text, HORIZONTAL_ALIGNMENT_LEFT, -1, font_size, Color("1b1530"))
	var label := "balls in the cup"
	var lw := font.get_string_size(label, HORIZONTAL_ALIGNMENT_LEFT, -1, LABEL_FONT_SIZE).x
	draw_string(
		font,
		Vector2(w * 0.5 - lw * 0.5, rim.end.y - 6.0),
		label,
		HORIZONTAL_ALIGNMENT_LEFT,
		-1,
		LABEL_FONT_SIZE,
		Color("2b2640")
	)
