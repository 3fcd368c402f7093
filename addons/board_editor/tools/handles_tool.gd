@tool
extends "res://addons/board_editor/tools/board_tool.gd"
## Drag handles: the ring's centre and radius, the launch rail's start, end and width, the
## gutter's ends (pachinko), the goal's radius (maze). Live preview, one undo step; right
## click or Escape while dragging puts the handle back.

const SetPropertiesAction := preload("res://addons/board_editor/actions/set_properties_action.gd")

const NAMES := {
	"ring_center": "Move ring",
	"ring_radius": "Resize ring",
	"rail_start_deg": "Move launch rail start",
	"rail_end_deg": "Move launch rail end",
	"rail_width": "Change launch rail width",
	"gutter_start_deg": "Move gutter start",
	"gutter_end_deg": "Move gutter end",
	"goal_radius": "Resize goal",
}

var _handle := ""
var _action: SetPropertiesAction = null


func press(at: Vector2, _event: InputEventMouseButton) -> bool:
	_handle = HitTest.pick_handle(level(), at, tolerance() * 1.5)
	if _handle.is_empty():
		return false
	_action = SetPropertiesAction.new(level(), {}, str(NAMES.get(_handle, "Change board")))
	return true


func motion(at: Vector2, _event: InputEventMouseMotion) -> bool:
	hover = at
	if _action == null:
		return false
	var point := session.snap_point(at) if _handle == "ring_center" else at
	_action.preview({_handle: HitTest.handle_value(level(), _handle, point)})
	return true


func release(_at: Vector2, _event: InputEventMouseButton) -> bool:
	if _action == null:
		return false
	if _action.is_applied():
		session.commit(_action, true)
	_action = null
	_handle = ""
	return true


func cancel() -> bool:
	if _action == null:
		return false
	_action.undo()
	_action = null
	_handle = ""
	return true


func draw(canvas: Control, to_screen: Transform2D) -> void:
	var board := level()
	if board.is_pachinko():
		var c := board.ring_center
		var rail_from := deg_to_rad(board.rail_start_deg)
		var rail_to := deg_to_rad(board.rail_end_deg)
		var inner := LaunchRail.guide_radius(board)
		OverlayDraw.board_arc(
			canvas, to_screen, c, inner, rail_from, rail_to, OverlayDraw.HANDLE_COLOR
		)
		var gutter_from := deg_to_rad(board.gutter_start_deg)
		var gutter_to := deg_to_rad(board.gutter_end_deg)
		var red := OverlayDraw.ERROR_COLOR
		OverlayDraw.board_arc(
			canvas, to_screen, c, board.ring_radius, gutter_from, gutter_to, red, 3.0
		)
	var hot := (
		HitTest.pick_handle(board, hover, tolerance() * 1.5) if _handle.is_empty() else _handle
	)
	var points := HitTest.handle_points(board)
	for handle: String in points:
		OverlayDraw.handle(canvas, to_screen, points[handle], handle == hot)
	if not hot.is_empty():
		var at := to_screen * points[hot] + Vector2(12, -12)
		OverlayDraw.label(canvas, at, str(NAMES.get(hot, hot)))
