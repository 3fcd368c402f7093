@tool
extends RefCounted
## The keyboard commands on a selection: delete, copy, paste, duplicate, nudge. Each one
## is a single undoable action; mirror mode takes the mirrored partners along.

const Session := preload("res://addons/board_editor/board_edit_session.gd")
const Items := preload("res://addons/board_editor/core/board_items.gd")
const Mirror := preload("res://addons/board_editor/core/mirror.gd")
const AddItemsAction := preload("res://addons/board_editor/actions/add_items_action.gd")
const DeleteItemsAction := preload("res://addons/board_editor/actions/delete_items_action.gd")
const MoveItemsAction := preload("res://addons/board_editor/actions/move_items_action.gd")


## Deletes the selection (and mirrored partners); false when there is nothing to delete.
static func delete_selection(session: Session) -> bool:
	var items := _editable(session)
	if session.mirror_enabled:
		items = Mirror.with_partners(session.level, items, Mirror.axis_of(session.level))
	if items.is_empty():
		return false
	session.commit(DeleteItemsAction.new(session.level, items))
	session.select([])
	return true


## Copies the selection to the session's clipboard, relative to its centre.
static func copy_selection(session: Session) -> bool:
	var items := _editable(session)
	if items.is_empty():
		return false
	session.clipboard = Items.extract(session.level, items, _centre(session.level, items))
	return true


## Pastes the clipboard centred at `at` (snapped) and selects what was pasted.
static func paste_at(session: Session, at: Vector2) -> bool:
	if session.clipboard.is_empty() or Items.set_size(session.clipboard) == 0:
		return false
	var data := Items.offset_set(session.clipboard, session.snap_point(at))
	var action := AddItemsAction.new(session.level, session.mirrored(data), "Paste board items")
	session.commit(action)
	session.select(action.added)
	return true


## Copies the selection one grid step (a cell on a maze) down and right, selecting the copy.
static func duplicate_selection(session: Session) -> bool:
	var items := _editable(session)
	if items.is_empty():
		return false
	var data := Items.extract(session.level, items, Vector2.ZERO)
	var offset := duplicate_offset(session, items)
	var action := AddItemsAction.new(
		session.level, Items.offset_set(data, offset), "Duplicate board items"
	)
	session.commit(action)
	session.select(action.added)
	return true


## Where Ctrl+D puts the copy: right of the original, clear of it by a ball's width (so the
## copy never overlaps it, an instant error), a whole number of grid steps away.
static func duplicate_offset(session: Session, items: Array[Vector2i]) -> Vector2:
	var level := session.level
	var bounds := Rect2()
	for k in items.size():
		var box := extent_of(level, items[k])
		bounds = box if k == 0 else bounds.merge(box)
	var grid := maxf(step(session), 1.0)
	var clear := bounds.size.x + level.ball_radius * 2.0
	return Vector2(ceilf(clear / grid) * grid, 0.0)


## The area an item covers on the board (its pins, cup, capsule or circle).
static func extent_of(level: BoardLevel, item: Vector2i) -> Rect2:
	var at := Items.position_of(level, item)
	var radius := 0.0
	match item.x:
		Items.Kind.PIN:
			radius = level.pin_radius
		Items.Kind.POCKET:
			var spec: PocketSpec = level.pockets[item.y]
			var cup := Rect2(at - Vector2(spec.width * 0.5, 0.0), Vector2(spec.width, spec.depth))
			return cup.grow(level.pin_radius)
		Items.Kind.BONUS:
			var bonus := level.bonus_pockets[item.y]
			return Rect2(at - Vector2(bonus.width * 0.5, 0.0), Vector2(bonus.width, bonus.depth))
		Items.Kind.WALL:
			var a := level.walls[item.y * 2]
			var b := level.walls[item.y * 2 + 1]
			return Rect2(a, Vector2.ZERO).expand(b).grow(level.wall_width * 0.5)
		Items.Kind.HOLE:
			radius = level.hole_radius
		Items.Kind.START:
			radius = level.ball_radius
	return Rect2(at, Vector2.ZERO).grow(radius)


## Moves the selection by `direction` grid steps (one pixel per step without snapping).
static func nudge(session: Session, direction: Vector2) -> bool:
	if session.selection.is_empty():
		return false
	var offset := direction * (step(session) if session.snap_enabled else 1.0)
	var action: MoveItemsAction
	if session.mirror_enabled:
		var axis := Mirror.axis_of(session.level)
		var anchor := Items.position_of(session.level, session.selection[0]).x
		var split := Mirror.split_for_move(session.level, session.selection, axis, anchor)
		var direct: Array[Vector2i] = split["direct"]
		var mirrored: Array[Vector2i] = split["mirrored"]
		var on_axis: Array[Vector2i] = split["on_axis"]
		action = MoveItemsAction.new(session.level, direct, offset, mirrored, on_axis)
	else:
		action = MoveItemsAction.new(session.level, session.selection, offset)
	session.commit(action)
	return true


## The step for duplicating and nudging: a maze cell on a snapped maze, else the grid.
static func step(session: Session) -> float:
	if session.level.is_maze() and session.snap_enabled:
		return session.level.path_width + session.level.wall_width
	return session.grid_step


# The selection without the goal, which cannot be copied or deleted.
static func _editable(session: Session) -> Array[Vector2i]:
	var items: Array[Vector2i] = []
	for item in session.selection:
		if item.x != Items.Kind.GOAL and Items.is_valid(session.level, item):
			items.append(item)
	return items


static func _centre(level: BoardLevel, items: Array[Vector2i]) -> Vector2:
	var box := Rect2(Items.position_of(level, items[0]), Vector2.ZERO)
	for item in items:
		box = box.expand(Items.position_of(level, item))
	return box.get_center()
