@tool
extends RefCounted
## Draws the editor's layer over the 2D viewport: the snap grid, the mirror axis, the
## selection, validation markers and the active tool's preview. The board itself is drawn
## by its BoardNode.

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const OverlayDraw := preload("res://addons/board_editor/ui/overlay_draw.gd")
const BoardTool := preload("res://addons/board_editor/tools/board_tool.gd")
const PinArc := preload("res://addons/board_editor/core/pin_arc.gd")

## Grid lines closer than this on screen are not drawn.
const MIN_GRID_PIXELS := 7.0


## Draws everything; `to_screen` maps board pixels to `canvas` pixels.
static func draw(
	canvas: Control,
	to_screen: Transform2D,
	session: BoardEditSession,
	tool: BoardTool,
	issues: Array[BoardIssue],
	focused_issue: int
) -> void:
	var level := session.level
	if session.snap_enabled:
		_draw_grid(canvas, to_screen, session)
	if session.mirror_enabled:
		var axis := session.mirror_axis()
		var top := to_screen * Vector2(axis, 0)
		var bottom := to_screen * Vector2(axis, level.size.y)
		canvas.draw_dashed_line(top, bottom, Color(0.9, 0.4, 1.0, 0.8), 1.5, 8.0)
	for item in session.selection:
		if BoardItems.is_valid(level, item):
			_draw_selected(canvas, to_screen, level, item)
	var arc := session.selected_arc()
	if not arc.is_empty():
		var pins: PackedInt32Array = arc["pins"]
		var ends := PackedVector2Array([level.pins[pins[0]], level.pins[pins[-1]]])
		OverlayDraw.center_mark(canvas, to_screen, PinArc.center_of(arc), ends)
	for i in issues.size():
		_draw_issue(canvas, to_screen, issues[i], i == focused_issue)
	tool.draw(canvas, to_screen)


static func _draw_grid(canvas: Control, to_screen: Transform2D, session: BoardEditSession) -> void:
	var level := session.level
	var step := session.grid_step
	var color := Color(1, 1, 1, 0.07)
	if level.is_maze() and level.path_width + level.wall_width > 0.0:
		step = level.path_width + level.wall_width
		color = Color(0.5, 0.8, 1.0, 0.18)
	if step * to_screen.get_scale().x < MIN_GRID_PIXELS:
		return
	var x := 0.0
	while x <= level.size.x + 0.01:
		OverlayDraw.line(canvas, to_screen, Vector2(x, 0), Vector2(x, level.size.y), color, 1.0)
		x += step
	var y := 0.0
	while y <= level.size.y + 0.01:
		OverlayDraw.line(canvas, to_screen, Vector2(0, y), Vector2(level.size.x, y), color, 1.0)
		y += step


# A frame round a selected item, 3 px outside its outline (ItemOutline.of_item).
static func _draw_selected(
	canvas: Control, to_screen: Transform2D, level: BoardLevel, item: Vector2i
) -> void:
	var color := OverlayDraw.SELECT_COLOR
	var outline := ItemOutline.of_item(ItemKinds.of_item(level, item), level, item.y)
	match outline.form:
		ItemOutline.Form.BOX:
			var box := outline.box.grow(outline.margin + 3.0)
			var screen := Rect2(to_screen * box.position, box.size * to_screen.get_scale())
			canvas.draw_rect(screen, color, false, 2.0)
		ItemOutline.Form.CAPSULE:
			OverlayDraw.line(canvas, to_screen, outline.center, outline.end, Color(color, 0.6), 4.0)
			OverlayDraw.circle(canvas, to_screen, outline.center, 3.0, color, true)
			OverlayDraw.circle(canvas, to_screen, outline.end, 3.0, color, true)
		_:
			var radius := outline.radius + outline.margin + 3.0
			OverlayDraw.circle(
				canvas, to_screen, outline.center, radius, color, false, outline.line_width
			)


static func _draw_issue(
	canvas: Control, to_screen: Transform2D, issue: BoardIssue, focused: bool
) -> void:
	var color := OverlayDraw.ERROR_COLOR if issue.is_error() else OverlayDraw.WARNING_COLOR
	var at := to_screen * issue.position
	if focused and issue.area.has_area():
		# The whole area the problem covers (both items, the ring), as the jump framed it.
		var box := Rect2(to_screen * issue.area.position, issue.area.size * to_screen.get_scale())
		OverlayDraw.dashed_rect(canvas, box.grow(4.0), Color(color, 0.9))
	# The walls the problem names (those that close a goal or a start in).
	var width := (6.0 if focused else 4.0) * to_screen.get_scale().x
	for k in range(0, issue.segments.size() - 1, 2):
		var a := to_screen * issue.segments[k]
		var b := to_screen * issue.segments[k + 1]
		canvas.draw_line(a, b, Color(color, 0.8 if focused else 0.5), maxf(width, 3.0), true)
	var radius := 11.0 if focused else 8.0
	canvas.draw_circle(at, radius, Color(color, 0.25))
	canvas.draw_arc(at, radius, 0.0, TAU, 24, color, 2.0 if focused else 1.5, true)
	var font := ThemeDB.fallback_font
	canvas.draw_string(font, at + Vector2(-3, 5), "!", HORIZONTAL_ALIGNMENT_LEFT, -1, 13, color)
	if focused:
		OverlayDraw.label(canvas, at + Vector2(radius + 8, 5), issue.message, color.lightened(0.5))
