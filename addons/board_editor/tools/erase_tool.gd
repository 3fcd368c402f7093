@tool
extends "res://addons/board_editor/tools/board_tool.gd"
## Click a thing to delete it (its mirror partner too in mirror mode). A pocket goes with
## all its pins; the goal cannot be erased, only moved.

const HitTest := preload("res://addons/board_editor/core/hit_test.gd")
const Mirror := preload("res://addons/board_editor/core/mirror.gd")
const DeleteItemsAction := preload("res://addons/board_editor/actions/delete_items_action.gd")


func press(at: Vector2, _event: InputEventMouseButton) -> bool:
	var item := HitTest.pick(level(), at, tolerance())
	if item == Items.NONE or item.x == Items.Kind.GOAL:
		return true
	var items: Array[Vector2i] = [item]
	if session.mirror_enabled:
		items = Mirror.with_partners(level(), items, Mirror.axis_of(level()))
	session.commit(DeleteItemsAction.new(level(), items))
	return true


func draw(canvas: Control, to_screen: Transform2D) -> void:
	var item := HitTest.pick(level(), hover, tolerance())
	if item == Items.NONE or item.x == Items.Kind.GOAL:
		return
	var at := Items.position_of(level(), item)
	Draw.circle(canvas, to_screen, at, 8.0 * pixel, Draw.ERROR_COLOR, false, 2.0)
	var arm := Vector2(5, 5)
	var center := to_screen * at
	canvas.draw_line(center - arm, center + arm, Draw.ERROR_COLOR, 2.0)
	canvas.draw_line(
		center + Vector2(-arm.x, arm.y), center + Vector2(arm.x, -arm.y), Draw.ERROR_COLOR, 2.0
	)
