@tool
extends "res://addons/board_editor/tools/board_tool.gd"
## Click to stamp the pin pattern set in the dock (row, lattice, arc, circle) centred at
## the snapped mouse position; the ghost shows exactly the pins it will add.

const PatternAction := preload("res://addons/board_editor/actions/pattern_action.gd")
const Mirror := preload("res://addons/board_editor/core/mirror.gd")


func press(at: Vector2, _event: InputEventMouseButton) -> bool:
	var action := PatternAction.new(
		level(), session.pattern, session.snap_point(at), session.mirror_axis()
	)
	if action.size() == 0:
		return true
	session.commit(action)
	session.select(action.added)
	return true


func draw(canvas: Control, to_screen: Transform2D) -> void:
	var points := PatternAction.points_for(session.pattern, session.snap_point(hover))
	if session.mirror_enabled:
		points = Mirror.with_reflections(points, session.mirror_axis())
	Draw.ghost_points(canvas, to_screen, points, level().pin_radius, level())
