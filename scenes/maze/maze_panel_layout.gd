class_name MazePanelLayout
extends RefCounted
## Where the maze screen's side panel goes for the window's shape: a column on the right of
## a landscape window, a band along the bottom of a portrait one, its text grown in a small
## window (MazeSideText) and the joystick sized to what the other lines leave. The board is
## framed in the rest, so no text lies over it.

## The column's share of a landscape window's width, within these bounds, this far from the
## edge; a portrait band's share of the height.
const SIDE_SHARE := 0.2
const SIDE_MIN_WIDTH := 260.0
const SIDE_MAX_WIDTH := 350.0
const SIDE_EDGE := 24.0
## A column whose text grew (a small window) is at most this share of the window's width.
const SIDE_MOST_SHARE := 0.36
const PORTRAIT_SIDE_SHARE := 0.45
## The narrowest the column goes for a wide board (design px, grown with the text).
const SIDE_NARROWEST := 225.0
## The margin the framing keeps round the board (MazeFraming.MARGIN_PX).
const BOARD_MARGIN := 8.0
## Layouts tried again, a frame apart, while the column has no width yet.
const RETRIES := 3
## The joystick's size in a landscape column, times the seed's (times the text's growth in a
## small window): one size on every board, big enough to grab, and under the narrowest
## column (a play trial found a ~25 px knob on First Roll, whose long hint and wide board
## left little room, and a large one on Switchbacks).
const JOYSTICK_SCALE := 1.0

## Frames after the screen opens or the window changes in which `place` works the layout
## out afresh while the wrapped text settles; after them the layout is kept for that window
## (a play trial saw the column narrow and the joystick shrink between attempts of one board,
## as it was worked out again for the texts of the moment).
const FRESH_FRAMES := 8

## Set by `place`: the layout must be tried again next frame.
var needs_retry := false

var _side: VBoxContainer
var _joystick: MazeJoystick
var _side_text: MazeSideText
var _retries_left := RETRIES
# The process frame until which `place` works the layout out afresh.
var _fresh_until := 0
# What the kept layout was worked out for (view, stretch, board aspect), and its board region.
var _kept_for: Array = []
var _kept_region := Rect2()
# Label -> the lines it keeps room for whatever it says now (reserve_lines).
var _reserved: Dictionary = {}


func _init(side: VBoxContainer, joystick: MazeJoystick) -> void:
	_side = side
	_joystick = joystick
	_side_text = MazeSideText.new(side)
	_fresh_until = Engine.get_process_frames() + FRESH_FRAMES


## Grows the panel's text for a view drawn `stretch` times its size (as `place` does first).
func place_text(stretch: float) -> void:
	_side_text.apply(stretch)


## Keeps room for `lines` lines of `label` whatever it says, so the panel does not move
## when its text wraps onto one more line (a play trial saw it jump 14 px under the pointer
## as the medal line changed to a two-line one).
func reserve_lines(label: Label, lines: int) -> void:
	_reserved[label] = lines
	_hold_reserved()


## The window changed: the retries start over and the layout is worked out afresh.
func window_changed() -> void:
	_retries_left = RETRIES
	_fresh_until = Engine.get_process_frames() + FRESH_FRAMES


## Places the panel for a view of `view` px drawn `stretch` times its size and returns the
## board's region. True in `needs_retry` afterwards when the column had no width yet (its
## wrapping lines stood one word a line): place it again next frame. `board_aspect` (the
## framed board's width over height, 0 when not known) lets the column narrow, down to what
## its text needs, for a board wider than the region's shape: such a board is drawn by its
## width, so each pixel the column gives up draws it bigger (a 900 × 700 window's balls
## were about 9 px on The Deep).
func place(view: Vector2, stretch: float, board_aspect := 0.0) -> Rect2:
	var asked := [view, stretch, board_aspect]
	if asked == _kept_for and not needs_retry and Engine.get_process_frames() > _fresh_until:
		return _kept_region  # the same window: the layout stays as it is
	_kept_region = _place(view, stretch, board_aspect)
	_kept_for = asked
	return _kept_region


func _place(view: Vector2, stretch: float, board_aspect: float) -> Rect2:
	needs_retry = false
	_side_text.apply(stretch)
	_hold_reserved()
	if view.x >= view.y:
		# the design's sizes, or bigger in a small window (900 × 700 drew them at 0.7): the
		# column widens with its text and the board takes the rest
		var width := clampf(view.x * SIDE_SHARE, SIDE_MIN_WIDTH, SIDE_MAX_WIDTH)
		width = minf(width * _side_text.factor, view.x * SIDE_MOST_SHARE)
		width = _narrowed(width, view, board_aspect)
		width = maxf(width, _lines_width())  # never narrower than its widest line
		_side.set_anchors_preset(Control.PRESET_RIGHT_WIDE)
		_side.offset_left = -width - SIDE_EDGE
		_side.offset_right = -SIDE_EDGE
		_side.offset_top = SIDE_EDGE
		_side.offset_bottom = -SIDE_EDGE
		var largest := minf(
			JOYSTICK_SCALE * _side_text.factor, width / MazeJoystick.drawn_size(1.0)
		)
		_fit_joystick(largest, view.y - SIDE_EDGE * 2.0)
		return Rect2(0.0, 0.0, view.x - width - SIDE_EDGE * 1.5, view.y)
	var height := view.y * PORTRAIT_SIDE_SHARE
	_side.set_anchors_preset(Control.PRESET_BOTTOM_WIDE)
	_side.offset_left = SIDE_EDGE
	_side.offset_right = -SIDE_EDGE
	_side.offset_top = -height
	_side.offset_bottom = -SIDE_EDGE * 0.5
	_fit_joystick(2.0, height - SIDE_EDGE * 0.5)
	return Rect2(0.0, 0.0, view.x, view.y - height)


# The column's `width` less what a board of `board_aspect` could use of it (the width it
# would be drawn at, filling the view's height), but never under the narrowest the column's
# own lines allow (SIDE_NARROWEST times the text's growth, or its widest unbreakable line).
func _narrowed(width: float, view: Vector2, board_aspect: float) -> float:
	if board_aspect <= 0.0:
		return width
	var wanted := board_aspect * (view.y - 2.0 * BOARD_MARGIN)
	var short := wanted - (view.x - width - SIDE_EDGE * 1.5 - 2.0 * BOARD_MARGIN)
	if short <= 0.0:
		return width
	var narrowest := maxf(SIDE_NARROWEST * _side_text.factor, _side.get_combined_minimum_size().x)
	return maxf(width - short, minf(narrowest, width))


# The width of the column's widest line that does not wrap (the joystick left out: it is
# sized to the column).
func _lines_width() -> float:
	var widest := 0.0
	for child in _side.get_children():
		var line := child as Control
		if line != null and line != _joystick and line.visible:
			widest = maxf(widest, line.get_combined_minimum_size().x)
	return widest


# Gives each reserved label the height of its reserved lines at its font size now.
func _hold_reserved() -> void:
	for label: Label in _reserved.keys():
		var font := label.get_theme_font(&"font")
		var font_size := MazeSideText.font_size_of(label)
		var line := font.get_height(font_size) + label.get_theme_constant(&"line_spacing")
		var lines: int = _reserved[label]
		label.custom_minimum_size.y = ceilf(line * lines)


# Sizes the joystick at most `largest` times the seed's size and no bigger than the height
# the panel's other lines leave of `panel_height` (px), so the whole panel fits its place.
func _fit_joystick(largest: float, panel_height: float) -> void:
	var stick := MazeJoystick.drawn_size(1.0)
	var others := _side.get_combined_minimum_size().y - _joystick.get_combined_minimum_size().y
	if others >= panel_height and _retries_left > 0:
		_retries_left -= 1
		needs_retry = true
		return
	_joystick.ui_scale = clampf((panel_height - others) / stick, 0.5, largest)
