@tool
extends ConfirmationDialog
## "Save board as": the designer names the board and picks its file, levels/<kind>/<id>.board.
## The file name follows the name as it is typed and can be edited; the path and any problem
## (a bad or taken name) show before Save is allowed. "New board…" is the same dialog with
## the board's kind to pick: it creates the board file and its level scene.

## The designer confirmed: `file_id` names levels/<kind>/<file_id>.board.
signal save_confirmed(file_id: String, display_name: String)
## The designer asked for a new board of `kind` (BoardLevel.Kind) named so.
signal new_board_confirmed(kind: int, file_id: String, display_name: String)

const BoardFiles := preload("res://addons/board_editor/ui/board_files.gd")
const NewBoardFiles := preload("res://addons/board_editor/core/new_board_files.gd")

var _kind := BoardLevel.Kind.PACHINKO
var _new_mode := false
var _kind_label: Label
var _kind_pick: OptionButton
var _name_field: LineEdit
var _id_field: LineEdit
var _path_label: Label
var _id_edited := false


func _init() -> void:
	title = "Save board as"
	ok_button_text = "Save"
	var grid := GridContainer.new()
	grid.columns = 2
	_kind_label = Label.new()
	_kind_label.text = "Game"
	grid.add_child(_kind_label)
	_kind_pick = OptionButton.new()
	_kind_pick.add_item("Pachinko", BoardLevel.Kind.PACHINKO)
	_kind_pick.add_item("Tilt maze", BoardLevel.Kind.MAZE)
	_kind_pick.item_selected.connect(
		func(index: int) -> void:
			_kind = _kind_pick.get_item_id(index) as BoardLevel.Kind
			_update()
	)
	grid.add_child(_kind_pick)
	_name_field = _row(grid, "Board name", "Shown in the level list, e.g. Tulip Garden")
	_id_field = _row(grid, "File name", "lower_case_with_underscores")
	_path_label = Label.new()
	_path_label.autowrap_mode = TextServer.AUTOWRAP_WORD_SMART
	_path_label.custom_minimum_size = Vector2(380, 0)
	var box := VBoxContainer.new()
	box.add_child(grid)
	box.add_child(_path_label)
	add_child(box)
	_name_field.text_changed.connect(_on_name_changed)
	_id_field.text_changed.connect(
		func(_text: String) -> void:
			_id_edited = true
			_update()
	)
	confirmed.connect(_on_confirmed)
	# Before the dialog's own Enter handler (connected next): letters typed in Enter's frame
	# are not reported yet, and Save / Create would still be greyed out for an empty name.
	_name_field.text_submitted.connect(func(_text: String) -> void: _take_typed(false))
	_id_field.text_submitted.connect(func(_text: String) -> void: _take_typed(true))
	register_text_enter(_id_field)
	register_text_enter(_name_field)


## Opens the dialog for `level`, starting from its current name.
func open_for(level: BoardLevel) -> void:
	_set_mode(false)
	_kind = level.kind
	_name_field.text = level.display_name
	_id_edited = false
	_id_field.text = BoardFiles.file_id_for(level.display_name)
	_update()
	popup_centered()
	_name_field.grab_focus()
	_name_field.select_all()


## Opens the dialog as "New board…": pick the game, name the board.
func open_new() -> void:
	_set_mode(true)
	_kind = _kind_pick.get_selected_id() as BoardLevel.Kind
	_name_field.text = ""
	_id_edited = false
	_id_field.text = ""
	_update()
	popup_centered()
	_name_field.grab_focus()


## The file the dialog would write now.
func chosen_path() -> String:
	return BoardFiles.path_for(_kind, _id_field.text)


func _row(grid: GridContainer, text: String, hint: String) -> LineEdit:
	var label := Label.new()
	label.text = text
	grid.add_child(label)
	var field := LineEdit.new()
	field.placeholder_text = hint
	field.custom_minimum_size = Vector2(260, 0)
	grid.add_child(field)
	return field


func _on_name_changed(text: String) -> void:
	if not _id_edited:
		_id_field.text = BoardFiles.file_id_for(text)
	_update()


func _set_mode(new_board: bool) -> void:
	_new_mode = new_board
	title = "New board" if new_board else "Save board as"
	ok_button_text = "Create" if new_board else "Save"
	_kind_label.visible = new_board
	_kind_pick.visible = new_board


func _problem() -> String:
	if _new_mode:
		return NewBoardFiles.problem(_kind, _id_field.text)
	return BoardFiles.new_file_problem(_kind, _id_field.text)


func _update() -> void:
	var problem := _problem()
	if _name_field.text.strip_edges().is_empty():
		problem = "Give the board a name."
	get_ok_button().disabled = not problem.is_empty()
	var writes := "Writes " + chosen_path()
	if _new_mode:
		writes += " and " + NewBoardFiles.scene_path_for(_kind, _id_field.text)
	_path_label.text = problem if not problem.is_empty() else writes
	var color := Color(1.0, 0.6, 0.4) if not problem.is_empty() else Color(0.7, 0.9, 0.7)
	_path_label.add_theme_color_override("font_color", color)


# A LineEdit reports typed text at the end of the frame: takes what the fields hold now.
# `from_id_field`: Enter was pressed in the file name, which counts as edited by hand when
# it is not what the name gives.
func _take_typed(from_id_field: bool) -> void:
	if from_id_field and _id_field.text != BoardFiles.file_id_for(_name_field.text):
		_id_edited = true
	_on_name_changed(_name_field.text)


func _on_confirmed() -> void:
	_on_name_changed(_name_field.text)  # letters typed in the frame of a click on Save
	if not _problem().is_empty():
		return
	if _new_mode:
		new_board_confirmed.emit(_kind, _id_field.text, _name_field.text.strip_edges())
	else:
		save_confirmed.emit(_id_field.text, _name_field.text.strip_edges())
