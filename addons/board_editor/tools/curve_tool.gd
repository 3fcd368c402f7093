@tool
extends "res://addons/board_editor/tools/board_tool.gd"
## Peg curve: drag a line or curve over the board and let go; pins follow it (CurvePins),
## as many as the dock says or one every spacing. One undo step; mirrored in mirror mode.
## Ghost pins show where they land, red where they would crowd a pin already there.

const CurvePins := preload("res://addons/board_editor/core/curve_pins.gd")
const Mirror := preload("res://addons/board_editor/core/mirror.gd")
const AddItemsAction := preload("res://addons/board_editor/actions/add_items_action.gd")

## Screen pixels the mouse must move before the curve takes another point.
const SAMPLE_PIXELS := 3.0

var _path := PackedVector2Array()


func press(at: Vector2, _event: InputEventMouseButton) -> bool:
	_path = PackedVector2Array([session.snap_point(at)])
	return true


func motion(at: Vector2, _event: InputEventMouseMotion) -> bool:
	hover = at
	if _path.is_empty():
		return false
	if at.distance_to(_path[_path.size() - 1]) >= SAMPLE_PIXELS * pixel:
		_path.append(at)
	return true


func release(at: Vector2, _event: InputEventMouseButton) -> bool:
	if _path.is_empty():
		return false
	_path.append(session.snap_point(at))
	var pins := pins_for(_path)
	_path = PackedVector2Array()
	if pins.is_empty():
		return true
	var data := BoardItems.empty_set()
	data["pins"] = pins
	var placed := session.mirrored(data)
	var placed_pins: PackedVector2Array = placed["pins"]
	var count := placed_pins.size()  # both halves when mirrored
	var action := AddItemsAction.new(level(), placed, "Add a %d-pin curve" % count)
	session.commit(action)
	session.select(action.added)
	return true


func cancel() -> bool:
	var busy := not _path.is_empty()
	_path = PackedVector2Array()
	return busy


## The pins a drawn `path` gives with the session's curve settings.
func pins_for(path: PackedVector2Array) -> PackedVector2Array:
	var count: int = session.curve["count"]
	var spacing: float = session.curve["spacing"]
	return CurvePins.along(path, count, spacing)


func draw(canvas: Control, to_screen: Transform2D) -> void:
	if _path.is_empty():
		OverlayDraw.circle(
			canvas, to_screen, session.snap_point(hover), 4.0, OverlayDraw.GHOST_COLOR
		)
		return
	var path := _path.duplicate()
	path.append(hover)
	var line := PackedVector2Array()
	for point in path:
		line.append(to_screen * point)
	canvas.draw_polyline(line, Color(OverlayDraw.GHOST_COLOR, 0.6), 1.5, true)
	var pins := pins_for(path)
	var mirrored := session.mirrored({"pins": pins})
	var shown: PackedVector2Array = mirrored.get("pins", pins)
	OverlayDraw.ghost_points(canvas, to_screen, shown, level().pin_radius, level())
	OverlayDraw.label(canvas, to_screen * hover + Vector2(14, -10), "%d pins" % pins.size())
