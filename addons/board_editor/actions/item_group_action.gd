@tool
extends BoardAction
## One edit applied to several items as one undo step: the property panel setting a field
## on every selected item. Each item's own edit (`build`: level, item → BoardAction or null)
## is made when the group is done, with the item found by its stable key (ItemKeys), so an
## edit that renumbers pins (a pocket stamping its rim again) never sends a later item's
## edit to the wrong pin. Undo takes the edits back in the reverse order; redo makes them
## again on the same board, so they land the same way.

const ItemKeys := preload("res://addons/board_editor/core/item_keys.gd")

var _keys: Array = []
var _build: Callable
var _name: String
var _done: Array[BoardAction] = []


## `items` (on `on_level` now) each get `build.call(level, item)`; `action_name` is the
## History entry.
func _init(
	on_level: BoardLevel, items: Array[Vector2i], build: Callable, action_name: String
) -> void:
	super(on_level)
	for item in items:
		var key := ItemKeys.of(on_level, item)
		if not key.is_empty():
			_keys.append(key)
	_build = build
	_name = action_name


func get_name() -> String:
	return _name


## Items the group edits (those still on the board).
func item_count() -> int:
	return _keys.size()


func do() -> void:
	if level == null:
		push_error("Board action '%s': no board to edit." % _name)
		return
	_done.clear()
	for key: Array in _keys:
		var found := ItemKeys.find_all(level, [key])
		if found.is_empty():
			continue
		var action: BoardAction = _build.call(level, found[0])
		if action != null:
			action.do()
			_done.append(action)
	_applied = true


func undo() -> void:
	if not _applied:
		return
	for i in range(_done.size() - 1, -1, -1):
		_done[i].undo()
	_applied = false
