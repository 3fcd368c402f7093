@tool
extends RefCounted
## Moves Godot's 2D view to a problem (jump-to-problem): frames its whole area, zooming out
## when the area is larger than the view and in (up to CLOSE_ZOOM) when the view is far out,
## then centres it. Godot offers no API for the 2D view, so this uses the two things the
## canvas editor exposes: its zoom widget and `center_at`; when either is missing (another
## Godot version) the view simply stays where it is.

## The zoom a jump brings a small problem to, at least (1 = 100 %).
const CLOSE_ZOOM := 2.0
## Share of the view the framed area may fill, so the area's edges stay in sight.
const FILL := 0.8
## The zoom range Godot's 2D view allows.
const ZOOM_RANGE := Vector2(1.0 / 128.0, 128.0)


## The zoom that shows `area_size` (canvas px) in a view of `view_size` (screen px) from a view
## at `current`: kept when the area fits and the view is close enough, else the nearest zoom
## that fits it, no closer than CLOSE_ZOOM.
static func zoom_for(current: float, area_size: Vector2, view_size: Vector2) -> float:
	var fits := INF
	if area_size.x > 0.0:
		fits = minf(fits, view_size.x * FILL / area_size.x)
	if area_size.y > 0.0:
		fits = minf(fits, view_size.y * FILL / area_size.y)
	var zoom := current
	if current > fits:
		zoom = fits  # out: the whole area in view
	elif current < minf(CLOSE_ZOOM, fits):
		zoom = minf(CLOSE_ZOOM, fits)  # in: close, but the whole area still in view
	return clampf(zoom, ZOOM_RANGE.x, ZOOM_RANGE.y)


## Frames `global_area` (canvas coordinates) in a view of `view_size` screen px.
static func show_area(global_area: Rect2, view_size: Vector2) -> bool:
	var main := EditorInterface.get_editor_main_screen()
	var editors := main.find_children("*", "CanvasItemEditor", true, false)
	if editors.is_empty() or not editors[0].has_method("center_at"):
		return false
	var editor: Node = editors[0]
	var widgets := editor.find_children("*", "EditorZoomWidget", true, false)
	if not widgets.is_empty() and widgets[0].has_method("get_zoom") and view_size.x > 0.0:
		var widget: Node = widgets[0]
		var zoom: float = widget.call("get_zoom")
		var wanted := zoom_for(zoom, global_area.size, view_size)
		if not is_equal_approx(wanted, zoom):
			widget.call("set_zoom", wanted)
			widget.emit_signal("zoom_changed", wanted)
	editor.call("center_at", global_area.get_center())
	return true
