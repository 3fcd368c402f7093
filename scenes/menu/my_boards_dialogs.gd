class_name MyBoardsDialogs
extends Node
## The dialogs of "My boards" in the level select: pick a board file to import, pick where to
## export one, confirm a delete. They only ask; the level select does the work when a choice
## is made (UserBoards). They wear the game's theme, sized to the window (big enough to read
## on a TV, never larger than the screen). An export writes only when the player confirms
## the file dialog, which shows the file's name and folder.

## The player picked a file to import.
signal import_chosen(source: String)
## The player picked where to write `board_path`'s file.
signal export_chosen(board_path: String, target: String)
## The player confirmed deleting `board_path`.
signal delete_confirmed(board_path: String)

const FILTERS := ["*.board ; Board files"]
const DIALOG_SIZE := Vector2i(1000, 640)
## The share of the window a dialog may take at most.
const WINDOW_SHARE := 0.92
const THEME := preload("res://scenes/menu/ui_theme.tres")

## The folder the file dialogs open in (tests point it at a scratch folder).
var start_folder := OS.get_system_dir(OS.SYSTEM_DIR_DOCUMENTS)

var _import_dialog: FileDialog = null
var _export_dialog: FileDialog = null
var _delete_dialog: ConfirmationDialog = null
var _export_path := ""
var _delete_path := ""


func _ready() -> void:
	_import_dialog = _file_dialog(FileDialog.FILE_MODE_OPEN_FILE, "Import a board")
	_import_dialog.file_selected.connect(func(path: String) -> void: import_chosen.emit(path))
	_export_dialog = _file_dialog(FileDialog.FILE_MODE_SAVE_FILE, "Export a board")
	_export_dialog.file_selected.connect(
		func(path: String) -> void: export_chosen.emit(_export_path, path)
	)
	_delete_dialog = ConfirmationDialog.new()
	_delete_dialog.theme = THEME
	_delete_dialog.title = "Delete a board"
	_delete_dialog.ok_button_text = "Delete"
	_delete_dialog.confirmed.connect(func() -> void: delete_confirmed.emit(_delete_path))
	add_child(_delete_dialog)


## Opens the file dialog that picks a board file to import.
func ask_import() -> void:
	_open_file_dialog(_import_dialog)


## Opens the file dialog that picks where to export `board_path` (named after its file).
func ask_export(board_path: String) -> void:
	_export_path = board_path
	_open_file_dialog(_export_dialog)
	_export_dialog.current_file = board_path.get_file()


## Asks whether to delete `board_path` (`shown_name` is what the player knows it by).
func ask_delete(board_path: String, shown_name: String) -> void:
	_delete_path = board_path
	var file_name := board_path.get_file()
	# the file is named once: a board that did not load is known by its file's name already
	var named := (
		'"%s"' % file_name if shown_name == file_name else '"%s" (%s)' % [shown_name, file_name]
	)
	_delete_dialog.dialog_text = (
		"Delete %s from My boards?\nThis removes the file; it cannot be undone." % named
	)
	_delete_dialog.reset_size()  # as small as its two lines: no blank half
	_delete_dialog.popup_centered()
	_delete_dialog.get_cancel_button().grab_focus()


## The text the delete dialog asks with (for tests).
func delete_question() -> String:
	return _delete_dialog.dialog_text


## The export dialog (tests read the file it would write).
func export_dialog() -> FileDialog:
	return _export_dialog


## The open dialog, or null when none is showing.
func open_dialog() -> Window:
	for dialog: Window in [_import_dialog, _export_dialog, _delete_dialog]:
		if dialog.visible:
			return dialog
	return null


func _file_dialog(mode: FileDialog.FileMode, title: String) -> FileDialog:
	var dialog := FileDialog.new()
	dialog.theme = THEME
	dialog.file_mode = mode
	dialog.access = FileDialog.ACCESS_FILESYSTEM
	dialog.filters = PackedStringArray(FILTERS)
	dialog.title = title
	dialog.use_native_dialog = false
	# one list of folders and board files, a path and a name: nothing a player must learn first
	dialog.display_mode = FileDialog.DISPLAY_LIST
	dialog.favorites_enabled = false
	dialog.recent_list_enabled = false
	dialog.layout_toggle_enabled = false
	dialog.file_sort_options_enabled = false
	dialog.hidden_files_toggle_enabled = false
	dialog.deleting_enabled = false
	dialog.overwrite_warning_enabled = true
	add_child(dialog)
	return dialog


func _open_file_dialog(dialog: FileDialog) -> void:
	dialog.current_dir = start_folder
	dialog.popup_centered(_fitted(DIALOG_SIZE))


# `wanted`, shrunk to fit the window (the visible part of the stretched viewport).
func _fitted(wanted: Vector2i) -> Vector2i:
	var room := Vector2i(get_viewport().get_visible_rect().size * WINDOW_SHARE)
	return Vector2i(mini(wanted.x, room.x), mini(wanted.y, room.y))
