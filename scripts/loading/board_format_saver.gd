@tool
class_name BoardFormatSaver
extends ResourceFormatSaver
## Saves a BoardLevel as a `.board` file (BoardTextWriter's reviewable text). A save that
## would write the same text leaves the file untouched, so opening a board and saving the
## scene never shows up as a change.

# Preloaded, not named by class: the engine registers this script while a fresh checkout's
# first import is still building the global class list, so BoardTextWriter is not known yet.
const Writer := preload("res://scripts/loading/board_text_writer.gd")
const EXTENSION := "board"


func _get_recognized_extensions(resource: Resource) -> PackedStringArray:
	return PackedStringArray([EXTENSION]) if resource is BoardLevel else PackedStringArray()


func _recognize(resource: Resource) -> bool:
	return resource is BoardLevel


func _recognize_path(_resource: Resource, path: String) -> bool:
	return path.get_extension().to_lower() == EXTENSION


# A .board file keeps its uid beside it in `<file>.uid` (the text has no room for one), as
# Godot does for every format without its own uid field. Without this, ResourceSaver.set_uid
# on a board failed with "File unrecognized".
func _set_uid(path: String, uid: int) -> Error:
	if path.get_extension().to_lower() != EXTENSION:
		return ERR_FILE_UNRECOGNIZED
	if uid == ResourceUID.INVALID_ID:
		return ERR_INVALID_PARAMETER
	var text := ResourceUID.id_to_text(uid) + "\n"
	var uid_path := path + ".uid"
	if FileAccess.file_exists(uid_path) and FileAccess.get_file_as_string(uid_path) == text:
		return OK
	var file := FileAccess.open(uid_path, FileAccess.WRITE)
	if file == null:
		return FileAccess.get_open_error()
	file.store_string(text)
	file.close()
	return OK


func _save(resource: Resource, path: String, _flags: int) -> Error:
	var level := resource as BoardLevel
	if level == null:
		return ERR_INVALID_PARAMETER
	var text := Writer.write(level)
	if FileAccess.file_exists(path) and FileAccess.get_file_as_string(path) == text:
		return OK
	# Write beside the file, then swap (SafeWrite): a failed write never leaves half a board
	# behind and a planted link is never written through.
	var written := SafeWrite.write_text(path, text)
	if written != OK:
		push_error("%s: could not write the board (%s)" % [path, error_string(written)])
	return written
