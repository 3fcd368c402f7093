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
	var kind := str(session.pattern["kind"])
	if kind in ["arc", "circle"] and not points.is_empty():
		# Spokes to an arc's two ends; none for a circle or for mirrored twin arcs.
		var ends := PackedVector2Array()
		if kind == "arc" and not session.mirror_enabled:
			ends = PackedVector2Array([points[0], points[points.size() - 1]])
		Draw.center_mark(canvas, to_screen, session.snap_point(hover), ends)
