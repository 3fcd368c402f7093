@tool
extends RefCounted
## Moves Godot's 2D view to a point (jump-to-problem): zooms in to at least MIN_ZOOM and
## centres the point. Godot offers no API for the 2D view, so this uses the two things the
## canvas editor exposes: its zoom widget and `center_at`; when either is missing (another
## Godot version) the view simply stays where it is.

## The zoom a jump uses at least (1 = 100 %).
const MIN_ZOOM := 2.0


## Centres the 2D view on `global_point` (canvas coordinates), zooming in when far out.
static func show_point(global_point: Vector2) -> bool:
	var main := EditorInterface.get_editor_main_screen()
	var editors := main.find_children("*", "CanvasItemEditor", true, false)
	if editors.is_empty() or not editors[0].has_method("center_at"):
		return false
	var editor: Node = editors[0]
	var widgets := editor.find_children("*", "EditorZoomWidget", true, false)
	if not widgets.is_empty() and widgets[0].has_method("get_zoom"):
		var widget: Node = widgets[0]
		var zoom: float = widget.call("get_zoom")
		if zoom < MIN_ZOOM:
			widget.call("set_zoom", MIN_ZOOM)
			widget.emit_signal("zoom_changed", MIN_ZOOM)
	editor.call("center_at", global_point)
	return true
