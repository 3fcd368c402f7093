@tool
extends "res://addons/board_editor/tools/board_tool.gd"
## Click to add a pocket whose mouth is centred at the snapped mouse position, with the
## width, depth and payout set in the dock; its rim pins and special pin are stamped.

const PocketAction := preload("res://addons/board_editor/actions/pocket_action.gd")


func press(at: Vector2, _event: InputEventMouseButton) -> bool:
	var action := PocketAction.new(
		level(),
		session.snap_point(at),
		session.pocket_width,
		session.pocket_depth,
		session.pocket_payout,
		session.mirror_axis()
	)
	session.commit(action)
	session.select(action.added)
	return true


func draw(canvas: Control, to_screen: Transform2D) -> void:
	var mouths := PackedVector2Array([session.snap_point(hover)])
	if session.mirror_enabled:
		mouths.append(Vector2(2.0 * session.mirror_axis() - mouths[0].x, mouths[0].y))
	for mouth in mouths:
		var spec := PocketSpec.create(
			mouth, session.pocket_width, session.pocket_depth, session.pocket_payout
		)
		var pins := PocketStamp.rim_pins(spec, level().pin_radius, level().ball_radius)
		Draw.ghost_points(canvas, to_screen, pins, level().pin_radius)
		var half := Vector2(spec.width * 0.5, 0)
		Draw.line(canvas, to_screen, mouth - half, mouth + half, Draw.GHOST_COLOR)
