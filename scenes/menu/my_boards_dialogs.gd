extends Node
## The dialogs of "My boards" in the level select: pick a board file to import, pick where to
## export one, confirm a delete. They only ask; the level select does the work when a choice
## is made (UserBoards).

## The player picked a file to import.
signal import_chosen(source: String)
## The player picked where to write `board_path`'s file.
signal export_chosen(board_path: String, target: String)
## The player confirmed deleting `board_path`.
signal delete_confirmed(board_path: String)

const FILTERS := ["*.board ; Board files"]
const DIALOG_SIZE := Vector2i(900, 560)

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
	_delete_dialog.title = "Delete a board"
	_delete_dialog.ok_button_text = "Delete"
	_delete_dialog.confirmed.connect(func() -> void: delete_confirmed.emit(_delete_path))
	add_child(_delete_dialog)


## Opens the file dialog that picks a board file to import.
func ask_import() -> void:
	_import_dialog.popup_centered(DIALOG_SIZE)


## Opens the file dialog that picks where to export `board_path` (named after its file).
func ask_export(board_path: String) -> void:
	_export_path = board_path
	_export_dialog.current_file = board_path.get_file()
	_export_dialog.popup_centered(DIALOG_SIZE)


## Asks whether to delete `board_path` (`shown_name` is what the player knows it by).
func ask_delete(board_path: String, shown_name: String) -> void:
	_delete_path = board_path
	_delete_dialog.dialog_text = (
		'Delete "%s" (%s) from My boards?\nThis removes the file; it cannot be undone.'
		% [shown_name, board_path.get_file()]
	)
	_delete_dialog.popup_centered()
	_delete_dialog.get_cancel_button().grab_focus()


## The open dialog, or null when none is showing.
func open_dialog() -> Window:
	for dialog: Window in [_import_dialog, _export_dialog, _delete_dialog]:
		if dialog.visible:
			return dialog
	return null


func _file_dialog(mode: FileDialog.FileMode, title: String) -> FileDialog:
	var dialog := FileDialog.new()
	dialog.file_mode = mode
	dialog.access = FileDialog.ACCESS_FILESYSTEM
	dialog.filters = PackedStringArray(FILTERS)
	dialog.title = title
	dialog.use_native_dialog = false
	dialog.current_dir = OS.get_system_dir(OS.SYSTEM_DIR_DOCUMENTS)
	add_child(dialog)
	return dialog
