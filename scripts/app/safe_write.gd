class_name SafeWrite
extends RefCounted
## Writes the game's files (boards, settings, best results, replays, the play-test request)
## without ever writing through a symbolic link someone planted: the bytes go to a fresh
## temporary file with an unguessable name beside the target, made only when nothing has that
## name, which then replaces the target. A folder under user:// that is a link is refused.

## Fresh temporary names tried before giving up (each is 64 random bits).
const TEMP_TRIES := 8


## The first folder or file of `path` below user:// that is a symbolic link, or "" when
## there is none (or `path` is not under user://).
static func link_on_path(path: String) -> String:
	if not path.begins_with("user://"):
		return ""
	var dir := DirAccess.open("user://")
	if dir == null:
		return ""
	var walked := "user://"
	for part in path.trim_prefix("user://").split("/", false):
		walked = walked.path_join(part)
		if dir.is_link(walked):
			return walked
	return ""


## Writes `bytes` to `path` through a fresh temporary file, so a failed write never leaves
## half a file and a planted link is never written through. OK or the error
## (ERR_FILE_CANT_WRITE when a folder on the way is a symbolic link: see link_on_path).
static func write_bytes(path: String, bytes: PackedByteArray) -> Error:
	if not link_on_path(path.get_base_dir()).is_empty():
		return ERR_FILE_CANT_WRITE
	var temp := _fresh_temp(path)
	if temp.is_empty():
		return ERR_ALREADY_EXISTS
	var file := FileAccess.open(temp, FileAccess.WRITE)
	if file == null:
		return FileAccess.get_open_error()
	file.store_buffer(bytes)
	var error := file.get_error()
	file.close()
	if error != OK:
		DirAccess.remove_absolute(temp)
		return error
	var moved := DirAccess.rename_absolute(temp, path)
	if moved != OK:
		DirAccess.remove_absolute(temp)
	return moved


## `write_bytes` for text (UTF-8).
static func write_text(path: String, text: String) -> Error:
	return write_bytes(path, text.to_utf8_buffer())


# A name beside `path` that nothing (no file, folder or link) has: ".<name>.<random>.partial"
# (the leading dot keeps it out of the board lists). "" when every try was taken.
static func _fresh_temp(path: String) -> String:
	var folder := path.get_base_dir()
	var dir := DirAccess.open(folder)
	if dir == null:
		return ""
	var crypto := Crypto.new()
	for _attempt in TEMP_TRIES:
		var token := crypto.generate_random_bytes(8).hex_encode()
		var temp := folder.path_join(".%s.%s.partial" % [path.get_file(), token])
		var taken := (
			FileAccess.file_exists(temp) or DirAccess.dir_exists_absolute(temp) or dir.is_link(temp)
		)
		if not taken:
			return temp
	return ""
