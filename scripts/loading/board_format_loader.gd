@tool
class_name BoardFormatLoader
extends ResourceFormatLoader
## Registers `.board` files with Godot (a global ResourceFormatLoader class is registered
## by the engine itself), so scenes, the Inspector, the editor's play-test and the game load
## boards through the same data-only reader: BoardTextReader, never the text resource parser.

# Preloaded, not named by class: the engine registers this script while a fresh checkout's
# first import is still building the global class list, so BoardTextReader is not known yet.
const Reader := preload("res://scripts/loading/board_text_reader.gd")
const EXTENSION := "board"


func _get_recognized_extensions() -> PackedStringArray:
	return PackedStringArray([EXTENSION])


func _handles_type(type: StringName) -> bool:
	return type == &"Resource" or type == &"BoardLevel"


func _get_resource_type(path: String) -> String:
	return "Resource" if path.get_extension().to_lower() == EXTENSION else ""


func _get_resource_script_class(path: String) -> String:
	return "BoardLevel" if path.get_extension().to_lower() == EXTENSION else ""


func _exists(path: String) -> bool:
	return FileAccess.file_exists(path)


func _load(path: String, _original_path: String, _sub_threads: bool, _cache_mode: int) -> Variant:
	var bytes := FileAccess.get_file_as_bytes(path)
	if bytes.is_empty() and FileAccess.get_open_error() != OK:
		push_error(
			(
				"%s: the file could not be read (%s)"
				% [path, error_string(FileAccess.get_open_error())]
			)
		)
		return ERR_CANT_OPEN
	var read := Reader.read_bytes(bytes)
	if read.has("error"):
		push_error("%s: %s" % [path, read["error"]])
		return ERR_FILE_CORRUPT
	return read["level"]
