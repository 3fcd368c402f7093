extends GutTest
## The "Save board as" / "New board" dialog writes the file name the board name gives, even
## when Enter comes in the same frame as the last letters typed. A LineEdit reports typed
## text (text_changed) at the end of the frame, so the file name field still held what the
## first letter gave: "Zz New" typed fast then Enter wrote levels/pachinko/z.board and
## scenes/boards/pachinko_z.tscn (seen in the editor under Xvfb).

const SaveAsDialog := preload("res://addons/board_editor/ui/save_as_dialog.gd")

var _confirmed: Array = []


func _dialog() -> SaveAsDialog:
	var dialog: SaveAsDialog = add_child_autofree(SaveAsDialog.new())
	dialog.new_board_confirmed.connect(
		func(kind: int, file_id: String, shown: String) -> void:
			_confirmed.append([kind, file_id, shown])
	)
	dialog.save_confirmed.connect(
		func(file_id: String, shown: String) -> void: _confirmed.append([-1, file_id, shown])
	)
	return dialog


func before_each() -> void:
	_confirmed.clear()


# The first letter arrives in a frame of its own; the rest land in the field without their
# text_changed yet, and Enter confirms.
func _type_fast_then_enter(dialog: SaveAsDialog, first: String, whole: String) -> void:
	var field: LineEdit = dialog._name_field
	field.text = first
	field.text_changed.emit(first)
	field.text = whole
	dialog.confirmed.emit()


func test_a_new_board_named_fast_gets_the_whole_name_as_its_file() -> void:
	var dialog := _dialog()
	dialog.open_new()
	_type_fast_then_enter(dialog, "Zq", "Zq Fast Board")
	dialog.hide()
	assert_eq(_confirmed.size(), 1)
	assert_eq(_confirmed[0][1], "zq_fast_board", "the file name follows the whole name")
	assert_eq(_confirmed[0][2], "Zq Fast Board")


func test_a_file_name_typed_by_hand_is_kept() -> void:
	var dialog := _dialog()
	dialog.open_new()
	var id_field: LineEdit = dialog._id_field
	id_field.text = "zq_my_own_file"
	id_field.text_changed.emit(id_field.text)
	_type_fast_then_enter(dialog, "Zq", "Zq Another")
	dialog.hide()
	assert_eq(_confirmed.size(), 1)
	assert_eq(_confirmed[0][1], "zq_my_own_file")


func test_enter_in_the_frame_of_the_typing_creates_the_board_at_once() -> void:
	var dialog := _dialog()
	dialog.open_new()
	var field: LineEdit = dialog._name_field
	field.text = "Zq All At Once"  # every letter and Enter in one frame: nothing reported
	field.text_submitted.emit(field.text)
	dialog.hide()
	assert_eq(_confirmed.size(), 1, "Enter is not lost on a greyed-out Create")
	assert_eq(_confirmed[0][1], "zq_all_at_once")


func test_a_file_name_typed_in_the_frame_of_enter_is_kept() -> void:
	var dialog := _dialog()
	dialog.open_new()
	var name_field: LineEdit = dialog._name_field
	name_field.text = "Zq Named"
	name_field.text_changed.emit(name_field.text)
	var id_field: LineEdit = dialog._id_field
	id_field.text = "zq_by_hand"
	id_field.text_submitted.emit(id_field.text)
	dialog.hide()
	assert_eq(_confirmed.size(), 1)
	assert_eq(_confirmed[0][1], "zq_by_hand")
