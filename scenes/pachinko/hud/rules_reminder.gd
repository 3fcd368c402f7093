class_name RulesReminder
extends PanelContainer
## The one-line reminder of how to shoot, over the top of the board, on every game after the
## first on a board (the first has the full rules card). It never blocks play: it ignores
## the mouse and fades away after SHOWN_SECONDS.

## Seconds the line stays fully on the screen before it fades, unless told otherwise.
const SHOWN_SECONDS := 5.0
## Seconds of its fade.
const FADE_SECONDS := 1.0
const FONT_SIZE := 18

## Seconds this one stays fully on the screen before it fades.
var shown_seconds := SHOWN_SECONDS

var _line := RichTextLabel.new()
var _fade: Tween
# The board's area the line is centred over (its size settles after its text is set), and
# the screen height its top keeps under (the board's name plate).
var _area := Rect2()
var _top := 0.0


func _init() -> void:
	mouse_filter = Control.MOUSE_FILTER_IGNORE
	visible = false
	var style := StyleBoxFlat.new()
	style.bg_color = Color(0.086, 0.055, 0.16, 0.88)
	style.border_color = Color(0.79, 0.63, 0.29)
	style.set_border_width_all(2)
	style.set_corner_radius_all(10)
	style.set_content_margin_all(8.0)
	style.content_margin_left = 16.0
	style.content_margin_right = 16.0
	add_theme_stylebox_override(&"panel", style)
	_line.bbcode_enabled = true
	_line.fit_content = true
	_line.autowrap_mode = TextServer.AUTOWRAP_OFF
	_line.scroll_active = false
	_line.mouse_filter = Control.MOUSE_FILTER_IGNORE
	_line.add_theme_font_size_override(&"normal_font_size", FONT_SIZE)
	_line.add_theme_font_size_override(&"bold_font_size", FONT_SIZE)
	add_child(_line)
	minimum_size_changed.connect(func() -> void: place(_area, _top))


## Shows `bbcode` (a line or two) and fades it out after `shown_seconds`.
func show_line(bbcode: String) -> void:
	_line.text = bbcode
	visible = true
	modulate.a = 1.0
	if _fade != null:
		_fade.kill()
	if not is_inside_tree():
		return
	_fade = create_tween()
	_fade.tween_interval(shown_seconds)
	_fade.tween_property(self, "modulate:a", 0.0, FADE_SECONDS)
	_fade.tween_callback(hide)


## Changes the line shown to `bbcode` without starting its time again (a number in it moved).
func retext(bbcode: String) -> void:
	_line.text = bbcode


## Takes the line away at once (a card came up over the board).
func dismiss() -> void:
	if _fade != null:
		_fade.kill()
	visible = false


## The line shown, without its markup (for tests).
func text() -> String:
	return _line.get_parsed_text()


## Places the lines centred across `area` (the board's area), their top at `top` (under the
## board's name plate: a play trial found the reminder over it) and kept inside the area.
func place(area: Rect2, top: float) -> void:
	_area = area
	_top = top
	size = get_combined_minimum_size()
	var x := clampf(area.get_center().x - size.x * 0.5, area.position.x, area.end.x - size.x)
	var y := clampf(top, area.position.y, maxf(area.end.y - size.y, area.position.y))
	position = Vector2(x, y)
