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
## that fits it, no closer than CLOSE_ZOOM. With `zoom_in` false the view only ever zooms
## out (to fit the area), never in: a balance table line brings its item into view at the
## designer's zoom.
static func zoom_for(
	current: float, area_size: Vector2, view_size: Vector2, zoom_in := true
) -> float:
	var fits := INF
	if area_size.x > 0.0:
		fits = minf(fits, view_size.x * FILL / area_size.x)
	if area_size.y > 0.0:
		fits = minf(fits, view_size.y * FILL / area_size.y)
	var zoom := current
	if current > fits:
		zoom = fits  # out: the whole area in view
	elif zoom_in and current < minf(CLOSE_ZOOM, fits):
		zoom = minf(CLOSE_ZOOM, fits)  # in: close, but the whole area still in view
	return clampf(zoom, ZOOM_RANGE.x, ZOOM_RANGE.y)


## Frames `global_area` (canvas coordinates) in `view`, the 2D viewport's control (the
## one the plugin draws its overlay on; its own scroll bars move the view); `zoom_in` as in
## zoom_for.
static func show_area(global_area: Rect2, view: Control, zoom_in := true) -> bool:
	var view_size := view.size
	var main := EditorInterface.get_editor_main_screen()
	var editors := main.find_children("*", "CanvasItemEditor", true, false)
	if editors.is_empty() or not editors[0].has_method("center_at"):
		return false
	var editor: Node = editors[0]
	var center := global_area.get_center()
	var zoom := 1.0
	var widgets := editor.find_children("*", "EditorZoomWidget", true, false)
	if not widgets.is_empty() and widgets[0].has_method("get_zoom") and view_size.x > 0.0:
		var widget: Node = widgets[0]
		zoom = widget.call("get_zoom")
		var wanted := zoom_for(zoom, global_area.size, view_size, zoom_in)
		if not is_equal_approx(wanted, zoom):
			widget.call("set_zoom", wanted)
			widget.emit_signal("zoom_changed", wanted)
			zoom = wanted
	# The view's scroll bars hold the canvas point at its top-left corner (Godot's
	# view_offset): setting them centres the area at the new zoom. `center_at` read a canvas
	# transform that lags a zoom change and landed thousands of pixels off.
	var h_bars := view.find_children("*", "HScrollBar", false, false)
	var v_bars := view.find_children("*", "VScrollBar", false, false)
	if h_bars.is_empty() or v_bars.is_empty() or view_size.x <= 0.0:
		editor.call("center_at", center)
		return true
	var corner := center - view_size / (2.0 * zoom)
	(h_bars[0] as ScrollBar).value = corner.x
	(v_bars[0] as ScrollBar).value = corner.y
	return true
