@tool
extends "res://addons/board_editor/tools/board_tool.gd"
## Click to stamp the pin pattern set in the dock (row, lattice, circle) centred at the
## snapped mouse position; the ghost shows exactly the pins it will add. An arc is placed by
## three points instead: press on one end and drag to the other (or click both ends), then
## move the mouse to bend the arc through it and click. An arc then runs exactly between the
## ends the designer chose and never bulges where it was not pulled. Escape or a right
## click drops the ends. One undo step; mirrored in mirror mode.

const PatternAction := preload("res://addons/board_editor/actions/pattern_action.gd")
const AddItemsAction := preload("res://addons/board_editor/actions/add_items_action.gd")
const Mirror := preload("res://addons/board_editor/core/mirror.gd")
const PinArc := preload("res://addons/board_editor/core/pin_arc.gd")
const ThreePointArc := preload("res://addons/board_editor/core/three_point_arc.gd")
## Screen pixels a press must be dragged to set the second end on release.
const DRAG_PIXELS := 6.0

# The arc's ends placed so far (0, 1 or 2 points).
var _ends := PackedVector2Array()


func press(at: Vector2, _event: InputEventMouseButton) -> bool:
	if not _is_arc():
		_stamp(at)
		return true
	var point := session.snap_point(at)
	if _ends.size() < 2:
		_ends.append(point)
		return true
	_place_arc(point)
	return true


func release(at: Vector2, _event: InputEventMouseButton) -> bool:
	if _is_arc() and _ends.size() == 1 and at.distance_to(_ends[0]) >= DRAG_PIXELS * pixel:
		_ends.append(session.snap_point(at))  # dragged from one end to the other
	return _is_arc()


func cancel() -> bool:
	var busy := not _ends.is_empty()
	_ends = PackedVector2Array()
	return busy


## The arc the placed ends and `bulge` make with the dock's pin count: PinArc keys, or
## {"error": why}.
func arc_for(bulge: Vector2) -> Dictionary:
	if _ends.size() < 2:
		return {"error": "Place both ends first."}
	var count: int = session.pattern.get("count", 0)
	return ThreePointArc.through(_ends[0], bulge, _ends[1], maxi(count, 2))


func _is_arc() -> bool:
	return str(session.pattern.get("kind", "")) == "arc"


func _stamp(at: Vector2) -> void:
	var action := PatternAction.new(
		level(), session.pattern, session.snap_point(at), session.mirror_axis()
	)
	if action.size() == 0:
		return
	session.commit(action)
	session.select(action.added)


func _place_arc(bulge: Vector2) -> void:
	var arc := arc_for(bulge)
	if arc.has("error"):
		return  # the ghost says why; the ends stay for another try
	var data := BoardItems.empty_set()
	data["pins"] = PinArc.points_of(arc)
	var placed := session.mirrored(data)
	var placed_pins: PackedVector2Array = placed["pins"]
	var action := AddItemsAction.new(level(), placed, "Add a %d-pin arc" % placed_pins.size())
	_ends = PackedVector2Array()
	session.commit(action)
	session.select(action.added)


func draw(canvas: Control, to_screen: Transform2D) -> void:
	if _is_arc():
		_draw_arc(canvas, to_screen)
		return
	var points := PatternAction.points_for(session.pattern, session.snap_point(hover))
	if session.mirror_enabled:
		points = Mirror.with_reflections(points, session.mirror_axis())
	OverlayDraw.ghost_points(canvas, to_screen, points, level().pin_radius, level())
	if str(session.pattern["kind"]) == "circle" and not points.is_empty():
		OverlayDraw.center_mark(canvas, to_screen, session.snap_point(hover), PackedVector2Array())


func _draw_arc(canvas: Control, to_screen: Transform2D) -> void:
	var at := session.snap_point(hover)
	if _ends.is_empty():
		OverlayDraw.handle(canvas, to_screen, at, false)
		OverlayDraw.label(canvas, to_screen * at + Vector2(14, -10), "Arc: press on one end")
		return
	if _ends.size() == 1:
		OverlayDraw.handle(canvas, to_screen, _ends[0], true)
		OverlayDraw.line(canvas, to_screen, _ends[0], at, OverlayDraw.GHOST_COLOR)
		OverlayDraw.handle(canvas, to_screen, at, false)
		OverlayDraw.label(canvas, to_screen * at + Vector2(14, -10), "Arc: the other end")
		return
	for end in _ends:
		OverlayDraw.handle(canvas, to_screen, end, true)
	var arc := arc_for(at)
	if arc.has("error"):
		OverlayDraw.line(canvas, to_screen, _ends[0], _ends[1], OverlayDraw.ERROR_COLOR)
		var why: String = arc["error"]
		OverlayDraw.label(canvas, to_screen * at + Vector2(14, -10), why, OverlayDraw.ERROR_COLOR)
		return
	var points := session.mirrored({"pins": PinArc.points_of(arc)})
	var shown: PackedVector2Array = points.get("pins", PackedVector2Array())
	OverlayDraw.ghost_points(canvas, to_screen, shown, level().pin_radius, level())
	OverlayDraw.handle(canvas, to_screen, at, false)
	OverlayDraw.label(
		canvas, to_screen * at + Vector2(14, -10), "Click to bend the arc through here"
	)
