@tool
extends RefCounted
## A plain undo stack for board actions, used where there is no editor: tests and the
## script that builds the shipped boards. In the editor, EditorUndoRedoManager does this.

var _done: Array[BoardAction] = []
var _undone: Array[BoardAction] = []


## Records an action; runs it first unless a live preview has already applied it.
func commit(action: BoardAction, already_applied := false) -> void:
	if not already_applied:
		action.do()
	_done.append(action)
	_undone.clear()


## Takes back the last action; false when there is none.
func undo() -> bool:
	if _done.is_empty():
		return false
	var action: BoardAction = _done.pop_back()
	action.undo()
	_undone.append(action)
	return true


## Applies the last undone action again; false when there is none.
func redo() -> bool:
	if _undone.is_empty():
		return false
	var action: BoardAction = _undone.pop_back()
	action.do()
	_done.append(action)
	return true


## The names of the recorded actions, oldest first.
func names() -> PackedStringArray:
	var result := PackedStringArray()
	for action in _done:
		result.append(action.get_name())
	return result
