@tool
extends "res://addons/board_editor/tools/board_tool.gd"
## Click to add a pocket whose mouth is centred at the snapped mouse position, with the
## width, depth and payout set in the dock; its rim pins and special pin are stamped.

const PocketAction := preload("res://addons/board_editor/actions/pocket_action.gd")
const PlacementCheck := preload("res://addons/board_editor/core/placement_check.gd")

var _check := PlacementCheck.new()


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
	var color := (
		OverlayDraw.BLOCKED_COLOR if would_add_error(mouths[0]) else OverlayDraw.GHOST_COLOR
	)
	for mouth in mouths:
		var spec := PocketSpec.create(
			mouth, session.pocket_width, session.pocket_depth, session.pocket_payout
		)
		var pins := PocketStamp.rim_pins(spec, level().pin_radius, level().ball_radius)
		for pin in pins:
			OverlayDraw.circle(canvas, to_screen, pin, level().pin_radius, color, true)
		var half := Vector2(spec.width * 0.5, 0)
		OverlayDraw.line(canvas, to_screen, mouth - half, mouth + half, color)


## True when a pocket with its mouth at `mouth` (and its mirror twin) would give the board a
## new error: the ghost turns red.
func would_add_error(mouth: Vector2) -> bool:
	var data := BoardItems.empty_set()
	var spec := PocketSpec.create(
		mouth, session.pocket_width, session.pocket_depth, session.pocket_payout
	)
	data["pockets"] = [spec]
	return _check.adds_error(level(), session.mirrored(data))
