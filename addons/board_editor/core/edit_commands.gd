@tool
extends RefCounted
## The keyboard commands on a selection: delete, copy, paste, duplicate, nudge, flip and
## mirror to the other half. Each one is a single undoable action; mirror mode takes the
## mirrored partners along.

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const BoardItems := preload("res://addons/board_editor/core/board_items.gd")
const Mirror := preload("res://addons/board_editor/core/mirror.gd")
const ItemKeys := preload("res://addons/board_editor/core/item_keys.gd")
const AddItemsAction := preload("res://addons/board_editor/actions/add_items_action.gd")
const DeleteItemsAction := preload("res://addons/board_editor/actions/delete_items_action.gd")
const MoveItemsAction := preload("res://addons/board_editor/actions/move_items_action.gd")
const FlipItemsAction := preload("res://addons/board_editor/actions/flip_items_action.gd")


## Deletes the selection (and mirrored partners); false when there is nothing to delete.
static func delete_selection(session: BoardEditSession) -> bool:
	var items := _editable(session)
	if session.mirror_enabled:
		items = Mirror.with_partners(session.level, items, Mirror.axis_of(session.level))
	if items.is_empty():
		return false
	session.commit(DeleteItemsAction.new(session.level, items))
	session.select([])
	return true


## Copies the selection to the session's clipboard, relative to its centre.
static func copy_selection(session: BoardEditSession) -> bool:
	var items := _editable(session)
	if items.is_empty():
		return false
	session.clipboard = BoardItems.extract(session.level, items, _centre(session.level, items))
	return true


## Pastes the clipboard centred at `at` (snapped) and selects what was pasted.
static func paste_at(session: BoardEditSession, at: Vector2) -> bool:
	if session.clipboard.is_empty() or BoardItems.set_size(session.clipboard) == 0:
		return false
	var data := BoardItems.offset_set(session.clipboard, session.snap_point(at))
	var action := AddItemsAction.new(session.level, session.mirrored(data), "Paste board items")
	session.commit(action)
	session.select(action.added)
	return true


## Copies the selection beside itself (duplicate_offset), selecting the copy. In mirror
## mode the copy's twin goes the other way on the other half, as a paste's does: a selection
## holding both twins is copied from one half only, so each copy comes once.
static func duplicate_selection(session: BoardEditSession) -> bool:
	var items := _editable(session)
	if items.is_empty():
		return false
	var source := items
	if session.mirror_enabled:
		source = _one_half(session.level, items, Mirror.axis_of(session.level))
	var data := BoardItems.extract(session.level, source, Vector2.ZERO)
	var offset := duplicate_offset(session, source)
	var copy := session.mirrored(BoardItems.offset_set(data, offset))
	var action := AddItemsAction.new(session.level, copy, "Duplicate board items")
	session.commit(action)
	session.select(action.added)
	return true


## Flips the selection left to right about its own centre (one undo step). In mirror mode
## the twins of the selected items flip too, about the reflected centre, so each stays the
## mirror image of its twin.
static func flip_selection(session: BoardEditSession) -> bool:
	var level := session.level
	var items: Array[Vector2i] = []
	for item in session.selection:
		if BoardItems.is_valid(level, item):
			items.append(item)
	if items.is_empty():
		return false
	var bounds := extent_of(level, items[0])
	for item in items:
		bounds = bounds.merge(extent_of(level, item))
	var centre := bounds.get_center().x
	var groups: Array = [[items, centre]]
	if session.mirror_enabled:
		var axis := Mirror.axis_of(level)
		var twins: Array[Vector2i] = []
		for item in items:
			var twin := Mirror.partner(level, item, axis)
			if twin != BoardItems.NONE and twin != item and not items.has(twin):
				twins.append(twin)
		if not twins.is_empty():
			groups.append([twins, 2.0 * axis - centre])
	session.commit(FlipItemsAction.new(level, groups))
	return true


## Adds the mirror image of the selection on the other half of the board (across the
## board's axis, Mirror.axis_of), keeping the originals; an item that already has its twin
## there, or sits on the axis, is not doubled. Selects the originals and the new twins.
## False when every selected item already has its twin.
static func mirror_to_other_half(session: BoardEditSession) -> bool:
	var level := session.level
	var axis := Mirror.axis_of(level)
	var items := _editable(session)
	var lonely: Array[Vector2i] = []
	for item in items:
		if Mirror.partner(level, item, axis) == BoardItems.NONE:
			lonely.append(item)
	if lonely.is_empty():
		return false
	var twins := Mirror.reflections_of(BoardItems.extract(level, lonely, Vector2.ZERO), axis)
	var action := AddItemsAction.new(
		level,
		twins,
		"Mirror %d item%s to the other half" % [lonely.size(), "" if lonely.size() == 1 else "s"]
	)
	var kept_keys: Array = []
	for item in items:
		kept_keys.append(ItemKeys.of(level, item))
	session.commit(action)
	var selected := ItemKeys.find_all(level, kept_keys)
	selected.append_array(action.added)
	session.select(selected)
	return true


## Where Ctrl+D puts the copy: right of the original, clear of it by a ball's width (so the
## copy never overlaps it, an instant error), a whole number of grid steps away.
static func duplicate_offset(session: BoardEditSession, items: Array[Vector2i]) -> Vector2:
	var level := session.level
	var bounds := Rect2()
	for k in items.size():
		var box := extent_of(level, items[k])
		bounds = box if k == 0 else bounds.merge(box)
	var grid := maxf(step(session), 1.0)
	var clear := bounds.size.x + level.ball_radius * 2.0
	return Vector2(ceilf(clear / grid) * grid, 0.0)


## The area an item covers on the board (its pins, cup, capsule or circle: its ItemKinds
## row's extent).
static func extent_of(level: BoardLevel, item: Vector2i) -> Rect2:
	return ItemKinds.of_item(level, item).extent(level, item.y)


## Moves the selection by `direction` grid steps (one pixel per step without snapping).
static func nudge(session: BoardEditSession, direction: Vector2) -> bool:
	if session.selection.is_empty():
		return false
	var offset := direction * (step(session) if session.snap_enabled else 1.0)
	var action: MoveItemsAction
	if session.mirror_enabled:
		var axis := Mirror.axis_of(session.level)
		var anchor := BoardItems.position_of(session.level, session.selection[0]).x
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
static func step(session: BoardEditSession) -> float:
	if session.level.is_maze() and session.snap_enabled:
		return session.level.path_width + session.level.wall_width
	return session.grid_step


# `items` without the twins on the right of `axis` whose left twin is in `items` too.
static func _one_half(level: BoardLevel, items: Array[Vector2i], axis: float) -> Array[Vector2i]:
	var half: Array[Vector2i] = []
	for item in items:
		var twin := Mirror.partner(level, item, axis)
		var on_right := BoardItems.position_of(level, item).x > axis
		if not (on_right and twin != item and items.has(twin)):
			half.append(item)
	return half


# The selection without the goal, which cannot be copied or deleted.
static func _editable(session: BoardEditSession) -> Array[Vector2i]:
	var items: Array[Vector2i] = []
	for item in session.selection:
		if item.x != BoardItems.Kind.GOAL and BoardItems.is_valid(session.level, item):
			items.append(item)
	return items


static func _centre(level: BoardLevel, items: Array[Vector2i]) -> Vector2:
	var box := Rect2(BoardItems.position_of(level, items[0]), Vector2.ZERO)
	for item in items:
		box = box.expand(BoardItems.position_of(level, item))
	return box.get_center()
