@tool
extends RefCounted
## The select tool's handles on a selected pin arc: its two ends and a bulge handle just
## outside the arc's middle. Dragging one reshapes the arc through the three points
## (ThreePointArc), live, every pin keeping its id, and lets go as one History step ("Edit
## pin arc"). Three points in a line bend no arc: the drag holds the last good shape and
## `problem` says why.

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const ThreePointArc := preload("res://addons/board_editor/core/three_point_arc.gd")
const EditArcAction := preload("res://addons/board_editor/actions/edit_arc_action.gd")
const OverlayDraw := preload("res://addons/board_editor/ui/overlay_draw.gd")
## Screen pixels the bulge handle sits outside the arc's middle (clear of the middle pin).
const BULGE_OUTSIDE := 16.0

## The handle being dragged: 0 first end, 1 bulge, 2 last end; -1 for none.
var handle := -1
## Why the last drag position gave no arc ("" when it did).
var problem := ""

var _session: BoardEditSession
var _arc: Dictionary = {}
var _points := PackedVector2Array()
var _bulge_offset := Vector2.ZERO
var _action: EditArcAction = null


## Where the handles of `session`'s selected arc are drawn ([] with no arc selected), for a
## view `pixel` board px per screen px.
static func handle_points(session: BoardEditSession, pixel: float) -> PackedVector2Array:
	var arc := session.selected_arc()
	if arc.is_empty():
		return PackedVector2Array()
	var points := ThreePointArc.handles(arc)
	points[1] += _outward(arc, points[1]) * BULGE_OUTSIDE * pixel
	return points


## The handle of the selected arc within `reach` board px of `at`, or -1.
static func handle_at(session: BoardEditSession, at: Vector2, reach: float, pixel: float) -> int:
	var points := handle_points(session, pixel)
	var best := -1
	var best_distance := reach
	for k in points.size():
		if points[k].distance_to(at) <= best_distance:
			best = k
			best_distance = points[k].distance_to(at)
	return best


## Starts dragging handle `index` of `session`'s selected arc.
func begin(session: BoardEditSession, index: int, pixel: float) -> void:
	_session = session
	_arc = session.selected_arc()
	_points = ThreePointArc.handles(_arc)
	_bulge_offset = _outward(_arc, _points[1]) * BULGE_OUTSIDE * pixel
	handle = index
	problem = ""
	_action = null


## Moves the dragged handle to `to`, reshaping the arc live.
func drag(to: Vector2) -> void:
	if handle < 0:
		return
	var points := _points.duplicate()
	points[handle] = to - _bulge_offset if handle == 1 else to
	var count: int = _arc["count"]
	var shape := ThreePointArc.through(points[0], points[1], points[2], count)
	if shape.has("error"):
		problem = shape["error"]
		return
	problem = ""
	if _action != null:
		_action.undo()
	var pins: PackedInt32Array = _arc["pins"]
	_action = EditArcAction.new(_session.level, pins, shape)
	_action.do()


## Ends the drag: the reshaped arc becomes one History step (nothing when it never moved).
func finish() -> void:
	var action := _action
	_action = null
	handle = -1
	problem = ""
	if action != null:
		_session.commit(action, true)
		_session.select(action.selected)


## Puts the arc back as it was before the drag.
func cancel() -> void:
	if _action != null:
		_action.undo()
	_action = null
	handle = -1
	problem = ""


## Draws `session`'s selected arc's handles (the dragged one hot), a stem from the arc's
## middle to the bulge handle, and a refused drag's reason.
func draw(canvas: Control, to_screen: Transform2D, session: BoardEditSession, pixel: float) -> void:
	var points := handle_points(session, pixel)
	if points.size() != 3:
		return
	var middle := ThreePointArc.handles(session.selected_arc())[1]
	OverlayDraw.line(canvas, to_screen, middle, points[1], OverlayDraw.HANDLE_COLOR)
	for k in points.size():
		OverlayDraw.handle(canvas, to_screen, points[k], handle == k)
	if not problem.is_empty() and handle >= 0:
		var at := to_screen * points[handle] + Vector2(14, -12)
		OverlayDraw.label(canvas, at, problem, OverlayDraw.ERROR_COLOR)


# Unit vector from the arc's centre through `point` (outward).
static func _outward(arc: Dictionary, point: Vector2) -> Vector2:
	var cx: float = arc["center_x"]
	var cy: float = arc["center_y"]
	return (point - Vector2(cx, cy)).normalized()
