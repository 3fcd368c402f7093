@tool
extends "res://addons/board_editor/tools/board_tool.gd"
## Click-drag a maze wall. With snapping on, both ends land on maze grid crossings and the
## wall runs along one grid line; with it off the wall goes exactly where you drag.

const WallAction := preload("res://addons/board_editor/actions/wall_action.gd")
const Snapping := preload("res://addons/board_editor/core/snapping.gd")

var _dragging := false
var _from := Vector2.ZERO


func press(at: Vector2, _event: InputEventMouseButton) -> bool:
	_dragging = true
	_from = session.snap_wall_point(at)
	hover = at
	return true


func motion(at: Vector2, _event: InputEventMouseMotion) -> bool:
	hover = at
	return _dragging


func release(at: Vector2, _event: InputEventMouseButton) -> bool:
	if not _dragging:
		return false
	_dragging = false
	var to := _end(at)
	if to.distance_to(_from) < 1.0:
		return true  # a click without a drag makes no wall
	var action := WallAction.new(level(), _from, to, session.mirror_axis())
	session.commit(action)
	session.select(action.added)
	return true


func cancel() -> bool:
	var busy := _dragging
	_dragging = false
	return busy


func draw(canvas: Control, to_screen: Transform2D) -> void:
	var width := maxf(level().wall_width * to_screen.get_scale().x, 2.0)
	if not _dragging:
		OverlayDraw.circle(
			canvas, to_screen, session.snap_wall_point(hover), 3.0, OverlayDraw.GHOST_COLOR
		)
		return
	var to := _end(hover)
	OverlayDraw.line(canvas, to_screen, _from, to, OverlayDraw.GHOST_COLOR, width)
	if session.mirror_enabled:
		var axis := session.mirror_axis()
		var from_image := Vector2(2 * axis - _from.x, _from.y)
		var to_image := Vector2(2 * axis - to.x, to.y)
		OverlayDraw.line(canvas, to_screen, from_image, to_image, OverlayDraw.GHOST_COLOR, width)


func _end(at: Vector2) -> Vector2:
	var to := session.snap_wall_point(at)
	if session.snap_enabled and level().is_maze():
		to = Snapping.straighten(_from, to)
	return to
