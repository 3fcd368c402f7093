@tool
extends RefCounted
## The board tool's file commands: the edited boards saved with the scene, "Save as" (the
## board named in one undo step, then written to levels/<kind>/<id>.board) and "New board"
## (a board file and its level scene written, the scene opened, its board node selected).
## The plugin composes one and hands it the dialog's parent and the session being edited.

## A board was named and written by Save as: its name and problems show again.
signal board_named
## A sentence for the designer (the dock's message line).
signal said(text: String)

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const BoardFiles := preload("res://addons/board_editor/ui/board_files.gd")
const NewBoardFiles := preload("res://addons/board_editor/core/new_board_files.gd")
const SaveAsDialog := preload("res://addons/board_editor/ui/save_as_dialog.gd")
const SetPropertiesAction := preload("res://addons/board_editor/actions/set_properties_action.gd")

var _dialog: SaveAsDialog
var _unsaved: Array[BoardLevel] = []
# `() -> BoardEditSession`: the session editing the selected board, null when none.
var _session_now: Callable


## Commands whose dialog lives under `parent` (the editor's base control) and act on the
## session `session_now` returns when they run.
func _init(parent: Control, session_now: Callable) -> void:
	_session_now = session_now
	_dialog = SaveAsDialog.new()
	_dialog.save_confirmed.connect(_save_as_named)
	_dialog.new_board_confirmed.connect(create_new_board)
	parent.add_child(_dialog)


## Frees the dialog (the plugin leaves the editor).
func free_dialog() -> void:
	_dialog.queue_free()


## Notes that `level` changed since the boards were last saved.
func mark_unsaved(level: BoardLevel) -> void:
	if not _unsaved.has(level):
		_unsaved.append(level)


## Saves every board changed since the last save that has its own file.
func save_boards() -> void:
	BoardFiles.save_all(_unsaved)
	_unsaved.clear()


## Opens the "Save board as" dialog for the edited board (nothing when none is edited).
func open_save_as() -> void:
	var session: BoardEditSession = _session_now.call()
	if session != null:
		_dialog.open_for(session.level)


## Opens the "New board" dialog (Project > Tools > New board..., or the dock's button).
func open_new_board_dialog() -> void:
	_dialog.open_new()


## Writes a new board and its level scene, opens the scene and selects its board node, so
## the tool is ready at once; `said` tells what went wrong otherwise.
func create_new_board(kind: int, file_id: String, display_name: String) -> void:
	var made := NewBoardFiles.create(kind, file_id, display_name)
	if made.has("error"):
		said.emit(str(made["error"]))
		return
	var board_path: String = made["board"]
	var scene_path: String = made["scene"]
	var filesystem := EditorInterface.get_resource_filesystem()
	filesystem.update_file(board_path)
	filesystem.update_file(scene_path)
	EditorInterface.open_scene_from_path(scene_path)
	var root := EditorInterface.get_edited_scene_root()
	if root is BoardNode:
		EditorInterface.get_selection().clear()
		EditorInterface.get_selection().add_node(root)
	said.emit("New board: %s and %s." % [board_path, scene_path])


# Names the board (one undo step) and writes it to levels/<kind>/<file_id>.board.
func _save_as_named(file_id: String, display_name: String) -> void:
	var session: BoardEditSession = _session_now.call()
	if session == null:
		return
	var level := session.level
	var names := {
		"display_name": display_name, "board_id": BoardFiles.board_id_for(level.kind, file_id)
	}
	session.commit(SetPropertiesAction.new(level, names, "Name board"))
	said.emit(BoardFiles.save_as_file(level, file_id))
	board_named.emit()
