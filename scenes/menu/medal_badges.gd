extends Control
## A level card's medal rows: per mode (easy, hard) a disc in gold, silver or bronze, or an
## empty ring with no medal yet, then the board's three target times, each beside its
## medal's colour; on a locked board, a padlock and what opens it instead.

const COLORS := {
	Medals.Medal.GOLD: Color("#f2c14e"),
	Medals.Medal.SILVER: Color("#c9d1d9"),
	Medals.Medal.BRONZE: Color("#cd7f4a"),
}
const FAINT := Color(1, 1, 1, 0.45)
const TIME_INK := Color(1, 1, 1, 0.8)
const RADIUS := 8.0
const FONT_SIZE := 15
const ROW_HEIGHT := 22.0
## Where the three target times start and how far apart they are (px).
const TIMES_X := 66.0
const TIME_STEP := 68.0

## Medal in easy and in hard mode (Medals.Medal).
var easy_medal := Medals.Medal.NONE
var hard_medal := Medals.Medal.NONE
## The board's [gold, silver, bronze] times per mode (empty: the board has none).
var easy_times := PackedFloat64Array()
var hard_times := PackedFloat64Array()
## A locked board shows a padlock and this text (what opens it) instead of medals.
var lock_text := ""


func _init() -> void:
	custom_minimum_size = Vector2(0, ROW_HEIGHT * 2.0 + 2.0)
	mouse_filter = Control.MOUSE_FILTER_IGNORE


## Shows these medals and each mode's target times, or the padlock and `locked_because`
## when that is not empty.
func show_medals(
	easy: Medals.Medal,
	hard: Medals.Medal,
	locked_because: String,
	times_easy := PackedFloat64Array(),
	times_hard := PackedFloat64Array()
) -> void:
	easy_medal = easy
	hard_medal = hard
	easy_times = times_easy
	hard_times = times_hard
	lock_text = locked_because
	tooltip_text = "\n".join(row_texts()) if lock_text.is_empty() else lock_text
	queue_redraw()


## One line per mode as a player would read it: "Easy: Bronze · gold 0:36.3, silver 0:53.2,
## bronze 1:24.7" (the medal held first, then the times to beat).
func row_texts() -> PackedStringArray:
	var lines := PackedStringArray()
	for row: Array in _rows():
		var times: PackedFloat64Array = row[2]
		var held: Medals.Medal = row[1]
		var line := "%s: %s" % [row[0], Medals.name_of(held)]
		if times.size() == 3:
			line += (
				" · gold %s, silver %s, bronze %s"
				% [_clock(times[0]), _clock(times[1]), _clock(times[2])]
			)
		lines.append(line)
	return lines


func _rows() -> Array:
	return [["Easy", easy_medal, easy_times], ["Hard", hard_medal, hard_times]]


func _draw() -> void:
	var mid := size.y * 0.5
	if not lock_text.is_empty():
		_draw_padlock(Vector2(RADIUS, mid))
		_draw_text(Vector2(RADIUS * 2.0 + 8.0, mid + 6.0), lock_text, FAINT)
		return
	var y := ROW_HEIGHT * 0.5
	for row: Array in _rows():
		var medal: int = row[1]
		var centre := Vector2(RADIUS, y)
		if COLORS.has(medal):
			var colour: Color = COLORS[medal]
			draw_circle(centre, RADIUS, colour)
			draw_circle(centre, RADIUS * 0.55, Color(1, 1, 1, 0.35), false, 1.5)
		else:
			draw_circle(centre, RADIUS - 1.0, FAINT, false, 1.5)
		var mode: String = row[0]
		_draw_text(Vector2(RADIUS * 2.0 + 6.0, y + 5.0), mode, FAINT)
		var times: PackedFloat64Array = row[2]
		if times.size() == 3:
			for k in 3:
				var x := TIMES_X + TIME_STEP * k
				var rank: int = Medals.Medal.GOLD - k
				var held := medal >= rank
				var dot: Color = COLORS[rank]
				draw_circle(Vector2(x + 4.0, y), 4.0, dot if held else Color(dot, 0.55))
				_draw_text(
					Vector2(x + 12.0, y + 5.0), _clock(times[k]), TIME_INK if not held else dot
				)
		y += ROW_HEIGHT


static func _clock(seconds: float) -> String:
	return MazeWinSummary.clock(seconds)


func _draw_text(at: Vector2, text: String, colour: Color) -> void:
	var font := get_theme_default_font()
	draw_string(font, at, text, HORIZONTAL_ALIGNMENT_LEFT, -1, FONT_SIZE, colour)


func _draw_padlock(centre: Vector2) -> void:
	draw_arc(centre + Vector2(0, -3), 5.5, PI, TAU, 12, FAINT, 2.5)
	draw_rect(Rect2(centre + Vector2(-8, -2), Vector2(16, 12)), FAINT)
