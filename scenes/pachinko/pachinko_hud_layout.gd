class_name PachinkoHudLayout
extends RefCounted
## Where the pachinko screen's panel goes and how big it is drawn: a column beside the board
## (drawn bigger in a small window, so its smallest words still read), or a band under the
## board in a portrait window. Returns the board's area; the game fits the board into it.

const HUD_WIDTH := 360.0
## Beside the board, the panel drawn bigger to read (a small window) takes at most this
## share of the window's width: the board keeps the rest.
const MOST_HUD_SHARE := 0.45
## A window this much taller than wide puts the panel under the board, at most this wide
## (view units before its zoom).
const PORTRAIT_HUD_HEIGHT := 720.0
const PORTRAIT_HUD_WIDTH := 760.0
const MARGIN := 10.0

var _hud: Control
var _column: BoxContainer
var _info: BoxContainer
var _launcher: LauncherPanel


func _init(hud: Control, column: BoxContainer, info: BoxContainer, launcher: LauncherPanel) -> void:
	_hud = hud
	_column = column
	_info = info
	_launcher = launcher


## Places the panel for a view of `view` units and returns the board's area.
func place(view: Vector2) -> Rect2:
	if is_portrait(view):
		# A portrait window: the board fills the width on top, the panel takes the band below
		# (a column beside the board left it a third of the screen).
		_fit_portrait(Rect2(0.0, view.x, view.x, view.y - view.x))
		return Rect2(Vector2(MARGIN, MARGIN), Vector2(view.x, view.x) - Vector2.ONE * MARGIN * 2.0)
	# a small window draws the column bigger, so its smallest words still read, and
	# wider by as much: the board takes what is left
	_info.vertical = true
	_launcher.size_flags_horizontal = Control.SIZE_FILL
	_launcher.draw_bigger(1.0)
	var zoom := minf(_readable_zoom(), view.x * MOST_HUD_SHARE / HUD_WIDTH)
	_hud.scale = Vector2.ONE * maxf(zoom, 1.0)
	_edge_toward_board(SIDE_LEFT)
	var hud_left := view.x - HUD_WIDTH * _hud.scale.x
	_hud.position = Vector2(hud_left, 0.0)
	_hud.size = Vector2(HUD_WIDTH, view.y / _hud.scale.y)
	return Rect2(Vector2(MARGIN, MARGIN), Vector2(hud_left - MARGIN * 2.0, view.y - MARGIN * 2.0))


## Fits the portrait band again (its text wrapped to the new width); nothing in landscape.
func refit(view: Vector2) -> void:
	if is_portrait(view):
		_fit_portrait(Rect2(0.0, view.x, view.x, view.y - view.x))


## True when a view of `view` units puts the panel under the board.
static func is_portrait(view: Vector2) -> bool:
	return view.y - view.x >= PORTRAIT_HUD_HEIGHT


# Lays the panel out in `band` under the board: the cup beside the numbers, the launcher
# under them, the whole drawn bigger so its smallest words read (ReadableText), as far as
# the band allows. The launcher then takes the height left under the numbers, drawn bigger
# (a player's thumb is there on a phone): with it at its design size the band's last
# 190 px stayed empty at 720 × 1280.
func _fit_portrait(band: Rect2) -> void:
	_info.vertical = false
	_launcher.size_flags_horizontal = Control.SIZE_SHRINK_CENTER
	_launcher.draw_bigger(1.0)
	_edge_toward_board(SIDE_TOP)
	var margins := Vector2(
		_column.offset_left - _column.offset_right, _column.offset_top - _column.offset_bottom
	)
	var needed := _column.get_combined_minimum_size() + margins
	var zoom := minf(_readable_zoom(), minf(band.size.x / needed.x, band.size.y / needed.y))
	var hud_size := Vector2(minf(band.size.x / zoom, PORTRAIT_HUD_WIDTH), band.size.y / zoom)
	_hud.scale = Vector2.ONE * zoom
	_hud.size = hud_size
	_hud.position = band.position + Vector2((band.size.x - hud_size.x * zoom) * 0.5, 0.0)
	var room := hud_size - margins
	var spare_height := room.y - (needed.y - margins.y)
	var design := LauncherPanel.DESIGN_SIZE
	_launcher.draw_bigger(minf(1.0 + spare_height / design.y, room.x / design.x))


# How much bigger the panel must be drawn for its smallest words (the launcher's) to read
# (ReadableText); 1 when they do as designed.
func _readable_zoom() -> float:
	var screen_scale := ReadableText.screen_scale_of(_hud)
	var wanted := ReadableText.growth_at(LauncherPanel.SMALL_FONT_SIZE, screen_scale)
	# rounded up, so the rounding of the scales on the way to the screen keeps it at 14
	return maxf(1.0, ceilf(wanted * 100.0) / 100.0)


# The panel's gold edge runs along the board: its left side beside it, its top under it.
func _edge_toward_board(side: Side) -> void:
	var style := _hud.get_theme_stylebox(&"panel") as StyleBoxFlat
	if style == null:
		return
	var width := maxi(style.border_width_left, style.border_width_top)
	style.border_width_left = width if side == SIDE_LEFT else 0
	style.border_width_top = width if side == SIDE_TOP else 0
