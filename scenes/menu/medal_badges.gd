class_name MedalBadges
extends Control
## A level card's medal rows: per mode (easy, hard) a disc in gold, silver or bronze, or an
## empty ring with no medal yet, then the board's three target times, each beside its
## medal's colour; on a locked board, a padlock and what opens it instead (wrapped to the
## two rows' height). The text is drawn at FONT_SIZE or bigger: a window that draws the
## card small (a portrait phone, a small window) gets it grown until it reads at 14 screen
## px (ReadableText), and the rows are laid out by the measured text, so they fit the card.

const COLORS := {
	Medals.Medal.GOLD: Color("#f2c14e"),
	Medals.Medal.SILVER: Color("#c9d1d9"),
	Medals.Medal.BRONZE: Color("#cd7f4a"),
}
const FAINT := Color(1, 1, 1, 0.45)
const TIME_INK := Color(1, 1, 1, 0.8)
const RADIUS := 8.0
## The text's size as designed (a 1280 × 720 window).
const FONT_SIZE := 15
## A row's height per unit of font size, and the room (px) between a row's parts.
const ROW_PER_FONT_UNIT := 22.0 / 15.0
const GAP := 6.0
const TIME_GAP := 10.0
const DOT_RADIUS := 4.0

## Medal in easy and in hard mode (Medals.Medal).
var easy_medal := Medals.Medal.NONE
var hard_medal := Medals.Medal.NONE
## The board's [gold, silver, bronze] times per mode (empty: the board has none).
var easy_times := PackedFloat64Array()
var hard_times := PackedFloat64Array()
## False for a board without black holes: hard mode plays the same there, so one row.
var has_hard := true
## A locked board shows a padlock and this text (what opens it) instead of medals.
var lock_text := ""

var _font_size := FONT_SIZE


func _init() -> void:
	mouse_filter = Control.MOUSE_FILTER_IGNORE
	_fit_height()
	set_notify_transform(true)


func _notification(what: int) -> void:
	if what == NOTIFICATION_ENTER_TREE:
		if not get_viewport().size_changed.is_connected(_refit):
			get_viewport().size_changed.connect(_refit)
		_refit()
	elif what == NOTIFICATION_TRANSFORM_CHANGED:
		_refit()


## The font size the rows are drawn at now (FONT_SIZE, or bigger to read at 14 screen px).
func font_size() -> int:
	return _font_size


## Screen pixels one unit of this control's font size takes now (its scale on the way to
## the screen times the window's stretch).
func screen_px_per_font_unit() -> float:
	if not is_inside_tree():
		return 1.0
	return (
		get_global_transform_with_canvas().get_scale().y
		* get_viewport().get_final_transform().get_scale().y
	)


## How wide the medal rows need to be drawn whole at the current font size (px).
func rows_width() -> float:
	var widest := 0.0
	for row: Array in _rows():
		var times: PackedFloat64Array = row[2]
		var width := _times_x()
		if times.size() == 3:
			for k in 3:
				width += DOT_RADIUS * 2.0 + 4.0 + _text_width(_clock(times[k])) + TIME_GAP
			width -= TIME_GAP
		widest = maxf(widest, width)
	return widest


## The lines the lock text is drawn in (1 or 2 when it fits the rows' height).
func lock_lines() -> int:
	if lock_text.is_empty():
		return 0
	var font := get_theme_default_font()
	var paragraph := TextParagraph.new()
	paragraph.add_string(lock_text, font, _font_size)
	paragraph.width = maxf(1.0, size.x - _lock_text_x())
	paragraph.break_flags = TextServer.BREAK_MANDATORY | TextServer.BREAK_WORD_BOUND
	return paragraph.get_line_count()


# The font grows with the card's scale on the screen; the rows' height follows it.
func _refit() -> void:
	var grown := ceili(FONT_SIZE * ReadableText.growth_at(FONT_SIZE, screen_px_per_font_unit()))
	if grown == _font_size:
		return
	_font_size = grown
	_fit_height()
	queue_redraw()


## The rows' height as designed (at FONT_SIZE).
static func designed_height() -> float:
	return _height_at(FONT_SIZE)


func _fit_height() -> void:
	custom_minimum_size = Vector2(0, _height_at(_font_size))


static func _height_at(text_size: int) -> float:
	return ceilf(text_size * ROW_PER_FONT_UNIT * 2.0 + 2.0)


func _row_height() -> float:
	return _font_size * ROW_PER_FONT_UNIT


## Shows these medals and each mode's target times, or the padlock and `locked_because`
## when that is not empty. `with_hard` false (a board without black holes, where hard mode
## plays the same) shows the easy row only (a play trial read a Hard row of the same times
## as clutter).
func show_medals(
	easy: Medals.Medal,
	hard: Medals.Medal,
	locked_because: String,
	times_easy := PackedFloat64Array(),
	times_hard := PackedFloat64Array(),
	with_hard := true
) -> void:
	has_hard = with_hard
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
	if not has_hard:
		return [["Easy", maxi(easy_medal, hard_medal), easy_times]]
	return [["Easy", easy_medal, easy_times], ["Hard", hard_medal, hard_times]]


func _draw() -> void:
	var mid := size.y * 0.5
	if not lock_text.is_empty():
		_draw_padlock(Vector2(RADIUS, mid))
		_draw_lock_text()
		return
	var row_height := _row_height()
	var y := row_height * 0.5
	var baseline := _font_size * 0.34
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
		_draw_text(Vector2(RADIUS * 2.0 + GAP, y + baseline), mode, FAINT)
		var times: PackedFloat64Array = row[2]
		if times.size() == 3:
			var x := _times_x()
			for k in 3:
				var rank: int = Medals.Medal.GOLD - k
				var held := medal >= rank
				var dot: Color = COLORS[rank]
				draw_circle(
					Vector2(x + DOT_RADIUS, y), DOT_RADIUS, dot if held else Color(dot, 0.55)
				)
				x += DOT_RADIUS * 2.0 + 4.0
				var clock := _clock(times[k])
				_draw_text(Vector2(x, y + baseline), clock, TIME_INK if not held else dot)
				x += _text_width(clock) + TIME_GAP
		y += row_height


# Where the times start: after the disc and the wider of the two modes' words.
func _times_x() -> float:
	var words := maxf(_text_width("Easy"), _text_width("Hard"))
	return RADIUS * 2.0 + GAP + words + TIME_GAP


func _text_width(text: String) -> float:
	var font := get_theme_default_font()
	return font.get_string_size(text, HORIZONTAL_ALIGNMENT_LEFT, -1, _font_size).x


func _lock_text_x() -> float:
	return RADIUS * 2.0 + 8.0


# What opens the board, wrapped to the card's width, centred on the rows' height.
func _draw_lock_text() -> void:
	var font := get_theme_default_font()
	var lines := lock_lines()
	var line_height := font.get_height(_font_size)
	var top := (size.y - line_height * lines) * 0.5 + font.get_ascent(_font_size)
	draw_multiline_string(
		font,
		Vector2(_lock_text_x(), top),
		lock_text,
		HORIZONTAL_ALIGNMENT_LEFT,
		size.x - _lock_text_x(),
		_font_size,
		2,
		FAINT
	)


static func _clock(seconds: float) -> String:
	return MazeWinSummary.clock(seconds)


func _draw_text(at: Vector2, text: String, colour: Color) -> void:
	var font := get_theme_default_font()
	draw_string(font, at, text, HORIZONTAL_ALIGNMENT_LEFT, -1, _font_size, colour)


func _draw_padlock(centre: Vector2) -> void:
	draw_arc(centre + Vector2(0, -3), 5.5, PI, TAU, 12, FAINT, 2.5)
	draw_rect(Rect2(centre + Vector2(-8, -2), Vector2(16, 12)), FAINT)
