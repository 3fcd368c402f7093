@tool
extends "res://addons/board_editor/tools/board_tool.gd"
## Select / move: click picks (shift adds, ctrl toggles), dragging empty space draws a
## selection box, dragging a selected item moves the selection (live, one undo step), and
## dragging an end dot of a wall selected on its own moves that end of that wall only, and
## a selected pin arc's handles (its ends and bulge) reshape it through three points.

const Mirror := preload("res://addons/board_editor/core/mirror.gd")
const MoveItemsAction := preload("res://addons/board_editor/actions/move_items_action.gd")
const SetPointAction := preload("res://addons/board_editor/actions/set_point_action.gd")
const ArcHandleDrag := preload("res://addons/board_editor/tools/arc_handle_drag.gd")

## Screen pixels the mouse must travel before a press becomes a drag.
const DRAG_START_PIXELS := 4.0

var _pressed := false
var _press_at := Vector2.ZERO
var _anchor := BoardItems.NONE
var _box_mode := 0  # 0 replace, 1 add (shift), 2 toggle (ctrl)
var _boxing := false
var _move: MoveItemsAction = null
# The wall end being dragged: its index in the points of its kind's field (`_end_field`,
# a SEGMENT kind's: the walls), -1 for none.
var _end_index := -1
var _end_field := ""
var _end_drag: SetPointAction = null
# Where the dragged end was when it was grabbed.
var _end_start := Vector2.ZERO
var _arc_drag := ArcHandleDrag.new()


func press(at: Vector2, event: InputEventMouseButton) -> bool:
	_pressed = true
	_press_at = at
	_box_mode = 1 if event.shift_pressed else (2 if event.ctrl_pressed else 0)
	_end_index = selected_wall_end(at) if _box_mode == 0 else -1
	if _end_index >= 0:
		_end_start = _end_points()[_end_index]
		return true  # a handle: the wall keeps its selection, only this end moves
	var arc_handle := -1
	if _box_mode == 0:
		arc_handle = ArcHandleDrag.handle_at(session, at, tolerance(), pixel)
	if arc_handle >= 0:
		_arc_drag.begin(session, arc_handle, pixel)
		return true  # the arc keeps its selection and changes shape
	_anchor = pick(at)
	var selection: Array[Vector2i] = session.selection
	if _anchor == BoardItems.NONE:
		_boxing = true
		return true
	var picked: Array[Vector2i] = selection.duplicate()
	if _box_mode == 2 and picked.has(_anchor):
		picked.erase(_anchor)
		_anchor = BoardItems.NONE
	elif _box_mode > 0 and not picked.has(_anchor):
		picked.append(_anchor)
	elif not picked.has(_anchor):
		picked = [_anchor]
	session.select(picked)
	return true


func motion(at: Vector2, _event: InputEventMouseMotion) -> bool:
	hover = at
	if not _pressed:
		return false
	if _boxing:
		return true
	if _end_index >= 0:
		_drag_end(at)
		return true
	if _arc_drag.handle >= 0 and at.distance_to(_press_at) >= DRAG_START_PIXELS * pixel:
		_arc_drag.drag(at)
	if _anchor == BoardItems.NONE or _arc_drag.handle >= 0:
		return true
	if _move == null and at.distance_to(_press_at) < DRAG_START_PIXELS * pixel:
		return true
	if _move == null:
		_move = _start_move()
	_move.preview(_snapped_delta(at - _press_at))
	return true


func release(at: Vector2, _event: InputEventMouseButton) -> bool:
	if not _pressed:
		return false
	_pressed = false
	if _boxing:
		_boxing = false
		_finish_box(Rect2(_press_at, at - _press_at))
	elif _arc_drag.handle >= 0:
		_arc_drag.finish()
	elif _end_index >= 0:
		_end_index = -1
		var drag := _end_drag
		_end_drag = null
		if drag != null:
			session.commit(drag, true)
	elif _move != null:
		var move := _move
		_move = null
		if move.delta == Vector2.ZERO:
			move.undo()
		else:
			session.commit(move, true)
	return true


func cancel() -> bool:
	var busy := _pressed
	_pressed = false
	_boxing = false
	_end_index = -1
	_arc_drag.cancel()
	if _end_drag != null:
		_end_drag.undo()
		_end_drag = null
	if _move != null:
		_move.undo()
		_move = null
	return busy


## The index in the board's `walls` points of the selected wall's end under `at`, or -1.
## Only a wall selected on its own has end handles (at a corner two walls share, only the
## selected one's end moves); with more selected, a drag moves the whole selection.
## An end grabs anywhere on the wall's round cap plus the pick tolerance (a press 7 px off
## the dot on a 10 px wall is the end's, not the whole wall's), but never past a third of
## the wall's length: the middle third always moves the whole wall.
func selected_wall_end(at: Vector2) -> int:
	if session.selection.size() != 1:
		return -1
	var best := -1
	for item: Vector2i in session.selection:
		if not BoardItems.is_valid(level(), item):
			continue
		var kind := ItemKinds.of_item(level(), item)
		if kind.shape != ItemKind.Shape.SEGMENT:
			continue
		_end_field = kind.field
		var wall := ItemOutline.of_item(kind, level(), item.y)
		var length := wall.center.distance_to(wall.end)
		var best_distance := minf(wall.radius + tolerance(), length / 3.0)
		best_distance = maxf(best_distance, minf(tolerance(), length * 0.5))
		for end in 2:
			var distance := (wall.end if end == 1 else wall.center).distance_to(at)
			if distance <= best_distance:
				best = item.y * 2 + end
				best_distance = distance
	return best


# The points of the field whose end is dragged (two a segment).
func _end_points() -> PackedVector2Array:
	return level().get(_end_field)


# Moves the dragged wall end by the drag so far (on the wall grid when snapping), live: an
# end grabbed beside its dot keeps that offset instead of jumping to the mouse.
func _drag_end(at: Vector2) -> void:
	if _end_drag == null and at.distance_to(_press_at) < DRAG_START_PIXELS * pixel:
		return
	var moved := _end_start + (at - _press_at)
	var to := session.snap_wall_point(moved) if session.snap_enabled else moved
	var other := _end_points()[_end_index + (1 if _end_index % 2 == 0 else -1)]
	if to.distance_to(other) < 1.0:
		return  # never fold a wall to nothing
	if _end_drag == null:
		_end_drag = SetPointAction.new(level(), _end_field, _end_index, to, "Move wall end")
	_end_drag.preview(to)


func draw(canvas: Control, to_screen: Transform2D) -> void:
	_arc_drag.draw(canvas, to_screen, session, pixel)
	if not _pressed:
		# What a click would pick.
		var under := pick(hover)
		if under != BoardItems.NONE:
			var at := to_screen * BoardItems.position_of(level(), under)
			canvas.draw_arc(at, 10.0, 0.0, TAU, 24, Color(OverlayDraw.SELECT_COLOR, 0.6), 1.0, true)
	if _boxing:
		var rect := Rect2(to_screen * _press_at, Vector2.ZERO).expand(to_screen * hover)
		canvas.draw_rect(rect, Color(0.4, 0.7, 1.0, 0.15), true)
		canvas.draw_rect(rect, Color(0.4, 0.7, 1.0, 0.9), false, 1.0)


func _start_move() -> MoveItemsAction:
	var selection: Array[Vector2i] = session.selection
	if session.mirror_enabled:
		var axis := Mirror.axis_of(level())
		var anchor_x := BoardItems.position_of(level(), _anchor).x
		var split := Mirror.split_for_move(level(), selection, axis, anchor_x)
		var direct: Array[Vector2i] = split["direct"]
		var mirrored: Array[Vector2i] = split["mirrored"]
		var on_axis: Array[Vector2i] = split["on_axis"]
		return MoveItemsAction.new(level(), direct, Vector2.ZERO, mirrored, on_axis)
	return MoveItemsAction.new(level(), selection, Vector2.ZERO)


# The drag offset that puts the grabbed item on the grid (a whole number of cells on a
# snapped maze, so walls stay on the lattice).
func _snapped_delta(raw: Vector2) -> Vector2:
	if not session.snap_enabled:
		return raw
	if level().is_maze():
		var cell := level().path_width + level().wall_width
		return (raw / cell).round() * cell if cell > 0.0 else raw
	var start := BoardItems.position_of(level(), _anchor)
	return session.snap_point(start + raw) - start


func _finish_box(rect: Rect2) -> void:
	var found: Array[Vector2i] = []
	found.assign(HitTest.in_rect(level(), rect).filter(session.can_pick))
	var selection: Array[Vector2i] = session.selection.duplicate()
	if _box_mode == 0:
		selection = found
	for item in found:
		if _box_mode == 2 and selection.has(item):
			selection.erase(item)
		elif not selection.has(item):
			selection.append(item)
	session.select(selection)
