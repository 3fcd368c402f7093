@tool
class_name BoardAction
extends RefCounted
## Base of every board edit: a plain object with `do()`, `undo()` and `get_name()`, so the
## plugin commits it through EditorUndoRedoManager and tests drive it with no editor.
##
## `do()` remembers the fields the action touches, then applies the change; `undo()` puts
## those fields back. Redo is `do()` again: the board is in the same state it was the first
## time, so the same change lands the same way.

const BoardFieldCopy := preload("res://addons/board_editor/core/board_field_copy.gd")

## The board this action edits.
var level: BoardLevel
var _before: Dictionary = {}
var _ids_after: Dictionary = {}
var _applied := false


func _init(on_level: BoardLevel) -> void:
	level = on_level


## Applies the change.
func do() -> void:
	if level == null:
		push_error("Board action '%s': no board to edit." % get_name())
		return
	var fields := _touched_fields()
	for kind in ItemKinds.listed():
		if fields.has(kind.field):
			fields.append(kind.id_field)
	_before = BoardFieldCopy.capture(level, fields)
	_apply()
	if _ids_after.is_empty():
		# Items that survived the edit keep their ids; new ones get fresh ids from the board's
		# counter. Undo puts the ids back with the lists but never the counter, so an id
		# handed out once is never handed out again.
		ItemIds.reconcile(level, _before)
		_ids_after = BoardFieldCopy.capture(level, _id_fields(fields))
	else:
		# A redo: the new items get the very ids they had the first time.
		BoardFieldCopy.restore(level, _ids_after)
	_applied = true
	level.notify_edited()


## Takes the change back.
func undo() -> void:
	if level == null or not _applied:
		return
	BoardFieldCopy.restore(level, _before)
	_applied = false
	level.notify_edited()


## The name shown in the editor's history.
func get_name() -> String:
	return "Edit board"


## True between a `do()` and the matching `undo()`.
func is_applied() -> bool:
	return _applied


# The id arrays among `fields`.
static func _id_fields(fields: PackedStringArray) -> PackedStringArray:
	var ids := PackedStringArray()
	for kind in ItemKinds.listed():
		if fields.has(kind.id_field):
			ids.append(kind.id_field)
	return ids


## The BoardLevel fields `_apply()` may change.
func _touched_fields() -> PackedStringArray:
	return PackedStringArray()


## The change itself; override.
func _apply() -> void:
	pass
