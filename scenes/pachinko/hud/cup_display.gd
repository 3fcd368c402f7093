class_name CupDisplay
extends Control
## The ball cup: a chrome tray heaped with balls (more balls, a bigger heap) and the count
## written large on its front. Paid balls pour in from above one after another
## (PayoutPour) and the count rises and bounces as they land. Its count is the one ball
## count the player reads: the side panel follows `shown_changed` (a ball in flight is not
## in it: it was shot, and comes back only as a pocket's payout).

## The count on the tray's front changed to `count` (a drop landed, a ball was shot, a
## payout came): anything that shows the player's balls follows it in the same frame.
signal shown_changed(count: int)

const MAX_HEAP := 40
const TRAY := Color("b9bfcc")
const TRAY_DARK := Color("4b5064")
## The font size of the words under the count.
const LABEL_FONT_SIZE := 15

var _count := 0
var _bump := 0.0
var _ball: Texture2D
var _pour := PayoutPour.new()
# The count last announced by shown_changed.
var _announced := -1


## The player has `balls` balls left to shoot (PachinkoRules.balls_to_shoot: the cup's and
## the one in the launcher, paid balls included); a rise bounces the number.
func set_count(balls: int) -> void:
	if balls > _count:
		_bump = 1.0
		set_process(true)
	_count = balls
	queue_redraw()
	_announce()


## Pours `balls` paid balls into the cup: they are in the count already, and it shows
## them as they land.
func pour(balls: int) -> void:
	_pour.pour(balls, size.x * 0.5, size.y * 0.45 + 12.0)
	if balls > 0:
		set_process(true)
		queue_redraw()
	_announce()


## Shows `balls` at once, the drops still falling landed: the win card and the tray then
## read the same number.
func catch_up(balls: int) -> void:
	_pour.land_all()
	set_count(balls)
	_announce()


## Drops still falling into the cup.
func pouring() -> int:
	return _pour.drops.size()


## The count shown: the cup's balls less those still on their way in.
func count() -> int:
	return maxi(_count - _pour.pending(), 0)


func _announce() -> void:
	var shown := count()
	if shown != _announced:
		_announced = shown
		shown_changed.emit(shown)


func _ready() -> void:
	_ball = BallLayer.make_ball_texture(32)
	custom_minimum_size = Vector2(300, 170)
	set_process(false)


func _process(delta: float) -> void:
	_bump = maxf(_bump - delta * 3.0, 0.0)
	if _pour.advance(delta) > 0:
		_bump = 1.0  # each landing drop bounces the count
		_announce()
	queue_redraw()
	if _bump <= 0.0 and _pour.drops.is_empty():
		set_process(false)


func _draw() -> void:
	var w := size.x
	var h := size.y
	var tray_top := h * 0.45
	var rim := Rect2(Vector2(w * 0.08, tray_top), Vector2(w * 0.84, h * 0.5))
	# The heap: rows of balls, narrower towards the top.
	var shown := mini(count(), MAX_HEAP)
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
	for drop in _pour.drops:
		var at := Vector2(drop.x, tray_top - drop.y)
		# a ball still above the cup's own area stays unseen: drawn there it fell over the
		# machine's name (a play trial's screenshot)
		if drop.w <= 0.0 and at.y >= r:
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
	var text := str(count())
	var tw := font.get_string_size(text, HORIZONTAL_ALIGNMENT_LEFT, -1, font_size).x
	var base := Vector2(w * 0.5 - tw * 0.5, rim.position.y + rim.size.y * 0.5 + font_size * 0.35)
	draw_string_outline(font, base, text, HORIZONTAL_ALIGNMENT_LEFT, -1, font_size, 6, TRAY_DARK)
	draw_string(font, base, text, HORIZONTAL_ALIGNMENT_LEFT, -1, font_size, Color("1b1530"))
	var label := "balls left to shoot"
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
