@tool
extends "res://addons/board_editor/tools/board_tool.gd"
## Click a thing to delete it, or drag across several: everything the brush passes over
## (the whole stroke between one mouse event and the next, not only the points the mouse
## reported) is marked and deleted together on release, as one undo step. In mirror mode the
## mirrored partners go too. A pocket goes with all its pins; the goal cannot be erased.

const Mirror := preload("res://addons/board_editor/core/mirror.gd")
const DeleteItemsAction := preload("res://addons/board_editor/actions/delete_items_action.gd")

var _erasing := false
var _marked: Array[Vector2i] = []
# Where the stroke was at the last mouse event (board px).
var _last := Vector2.ZERO


func press(at: Vector2, _event: InputEventMouseButton) -> bool:
	_erasing = true
	_marked.clear()
	_last = at
	_mark(at)
	return true


func motion(at: Vector2, _event: InputEventMouseMotion) -> bool:
	hover = at
	if _erasing:
		_mark_along(_last, at)
		_last = at
	return _erasing


func release(_at: Vector2, _event: InputEventMouseButton) -> bool:
	if not _erasing:
		return false
	_erasing = false
	var items: Array[Vector2i] = _marked.duplicate()
	_marked.clear()
	if session.mirror_enabled:
		items = Mirror.with_partners(level(), items, Mirror.axis_of(level()))
	if not items.is_empty():
		session.commit(DeleteItemsAction.new(level(), items))
	return true


func cancel() -> bool:
	var busy := _erasing
	_erasing = false
	_marked.clear()
	return busy


func draw(canvas: Control, to_screen: Transform2D) -> void:
	var shown: Array[Vector2i] = _marked.duplicate()
	var under := _erasable(hover)
	if under != BoardItems.NONE and not shown.has(under):
		shown.append(under)
	for item in shown:
		if not BoardItems.is_valid(level(), item):
			continue
		var center := to_screen * BoardItems.position_of(level(), item)
		var arm := Vector2(5, 5)
		canvas.draw_arc(center, 9.0, 0.0, TAU, 24, OverlayDraw.ERROR_COLOR, 2.0, true)
		canvas.draw_line(center - arm, center + arm, OverlayDraw.ERROR_COLOR, 2.0)
		canvas.draw_line(
			center + Vector2(-5, 5), center + Vector2(5, -5), OverlayDraw.ERROR_COLOR, 2.0
		)


func _mark(at: Vector2) -> void:
	var item := _erasable(at)
	if item != BoardItems.NONE and not _marked.has(item):
		_marked.append(item)


# Marks everything the brush touches on its way from `from` to `to`.
func _mark_along(from: Vector2, to: Vector2) -> void:
	for item in HitTest.along(level(), from, to, tolerance()):
		if session.can_pick(item) and not _marked.has(item):
			_marked.append(item)


func _erasable(at: Vector2) -> Vector2i:
	var item := pick(at)
	if item == BoardItems.NONE or not ItemKinds.of_pick(item.x).erasable:
		return BoardItems.NONE
	return item
