class_name UserBoards
extends RefCounted
## The player's own boards ("My boards"): `.board` files in user://boards/<kind>/. Import
## copies a file from anywhere into that folder only after it passes the same reader and
## validator as every board (a refused file writes nothing); export writes a board's file,
## byte for byte, wherever the player chooses; delete removes one file from the folder.
## Shipped boards (res://levels/) are never written or removed here.

## How many "_2", "_3", ... suffixes are tried before an import gives up on a name.
const MAX_CLASH_SUFFIX := 999


## Imports the board file at `source` (any path the player picked or dropped). Returns
## {"path": the new user:// file, "result": its BoardLoadResult} or {"error": why not, naming
## the file}. Nothing is written unless the board loads and validates.
static func import_file(source: String, root: String = BoardLoader.USER_DIR) -> Dictionary:
	var shown := source.get_file()
	if source.get_extension().to_lower() != "board":
		return {"error": "%s: only .board files can be imported" % shown}
	var file := FileAccess.open(source, FileAccess.READ)
	if file == null:
		var why := error_string(FileAccess.get_open_error())
		return {"error": "%s: the file could not be read (%s)" % [shown, why]}
	var limit: int = BoardSchema.MAX_FILE_BYTES
	if file.get_length() > limit:
		return {"error": "%s: the file is larger than %d bytes" % [shown, limit]}
	var bytes := file.get_buffer(file.get_length())
	file.close()
	var checked := BoardLoader.load_bytes(bytes, shown)
	if not checked.ok():
		return {"error": checked.error}
	var folder := "%s/%s" % [root, BoardLevel.kind_name(checked.level.kind)]
	var link := SafeWrite.link_on_path(folder)
	if not link.is_empty():
		return {
			"error":
			"%s: %s is a symbolic link; boards are only written to real folders" % [shown, link]
		}
	var made := DirAccess.make_dir_recursive_absolute(folder)
	if made != OK:
		return {"error": "%s: could not create %s (%s)" % [shown, folder, error_string(made)]}
	var target := free_path(folder, BoardFileName.safe_stem(source.get_file().get_basename()))
	if target.is_empty():
		return {"error": "%s: too many boards with this name in %s" % [shown, folder]}
	var written := write_bytes(target, bytes)
	if written != OK:
		return {"error": "%s: could not write %s (%s)" % [shown, target, error_string(written)]}
	var roots: Array[String] = [root + "/"]
	return {"path": target, "result": BoardLoader.load_board(target, roots)}


## `import_file` as one BoardLoadResult, the form BoardListLoading hands back, so imports
## run off the main thread: the new file's result (its path is the file in My boards), or a
## result with no level whose error says why `source` was not imported.
static func import_result(source: String, _kind: int, root: String) -> BoardLoadResult:
	var outcome := import_file(source, root)
	if outcome.has("result"):
		return outcome["result"]
	var refused := BoardLoadResult.new()
	refused.path = source
	refused.error = outcome["error"]
	return refused


## `<folder>/<stem>.board` if no file has that name, else the first free `<stem>_N.board`;
## "" when every suffix up to MAX_CLASH_SUFFIX is taken.
static func free_path(folder: String, stem: String) -> String:
	var candidate := "%s/%s.board" % [folder, stem]
	var suffix := 2
	while FileAccess.file_exists(candidate) or DirAccess.dir_exists_absolute(candidate):
		if suffix > MAX_CLASH_SUFFIX:
			return ""
		candidate = "%s/%s_%d.board" % [folder, stem, suffix]
		suffix += 1
	return candidate


## Writes the board file at `board_path` (a shipped or a player's board) to `target`, byte
## for byte. OK or the error; `target` gets ".board" added when it has no extension.
## `roots` are the folders a board may be exported from.
static func export_file(
	board_path: String, target: String, roots: Array[String] = BoardLoader.BOARD_ROOTS
) -> Error:
	if BoardLoader.path_problem(board_path, roots) != "":
		return ERR_FILE_BAD_PATH
	if not FileAccess.file_exists(board_path):
		return ERR_FILE_NOT_FOUND
	var bytes := FileAccess.get_file_as_bytes(board_path)
	if bytes.is_empty() and FileAccess.get_open_error() != OK:
		return FileAccess.get_open_error()
	if target.get_extension().is_empty():
		target += ".board"
	return write_bytes(target, bytes)


## Deletes one of the player's boards. Refuses (ERR_FILE_BAD_PATH) anything that is not a
## .board file directly inside `<root>/<kind>/`: shipped boards can never be deleted.
static func delete_file(board_path: String, root: String = BoardLoader.USER_DIR) -> Error:
	if not is_user_board(board_path, root):
		return ERR_FILE_BAD_PATH
	if not FileAccess.file_exists(board_path):
		return ERR_FILE_NOT_FOUND
	return DirAccess.remove_absolute(board_path)


## True for a path of a .board file in one of `<root>/<kind>/` (a player's board).
static func is_user_board(board_path: String, root: String = BoardLoader.USER_DIR) -> bool:
	var roots: Array[String] = [root + "/"]
	if not board_path.begins_with(root + "/") or board_path.get_extension() != "board":
		return false
	if BoardLoader.path_problem(board_path, roots) != "":
		return false
	var folder := board_path.get_base_dir()
	if folder.get_base_dir() != root:
		return false
	for kind: int in [BoardLevel.Kind.PACHINKO, BoardLevel.Kind.MAZE]:
		if folder.get_file() == BoardLevel.kind_name(kind):
			return true
	return false


## Writes `bytes` to `path` through a fresh temporary file (SafeWrite): a failed write never
## leaves half a board behind, and a planted link is never written through.
static func write_bytes(path: String, bytes: PackedByteArray) -> Error:
	return SafeWrite.write_bytes(path, bytes)
