class_name ReplayStore
extends RefCounted
## Replay files: where the games keep them (user://replays/), reading and writing them, and
## finding the board a replay was recorded on. Reading goes through ReplayReader (data only,
## every field checked), with the file's size checked before it is read.

## The folder of the games' own replays.
const DIR := "user://replays"
## Where a board is looked for, in order: the shipped boards, then the player's.
const BOARD_ROOTS: Array[String] = ["res://levels", "user://boards"]

## Where the games keep their replays: DIR, or a test's own folder (so tests never touch
## the player's replays).
static var folder := DIR


## The best maze run on a board in a mode: user://replays/maze_<board>_<easy|hard>.replay
## (a board id "maze_classic" gives maze_classic_easy.replay).
static func best_maze_path(board_id: String, hard: bool) -> String:
	var mode := "hard" if hard else "easy"
	return "%s/maze_%s_%s.replay" % [folder, file_safe(board_id, "maze_"), mode]


## The last pachinko game on a board: user://replays/pachinko_<board>_last.replay.
static func last_pachinko_path(board_id: String) -> String:
	return "%s/pachinko_%s_last.replay" % [folder, file_safe(board_id, "pachinko_")]


## A board id as a file name part, less `kind_prefix`: letters, digits, - and _ kept,
## anything else as _.
static func file_safe(board_id: String, kind_prefix := "") -> String:
	var out := ""
	for character in board_id.trim_prefix(kind_prefix):
		var ok := character.is_valid_identifier() or character.is_valid_int() or character == "-"
		out += character if ok else "_"
	return out


## Writes `replay` to `path` (its folder made when missing). Returns OK or the file error;
## a null replay (nothing recorded, or too long) writes nothing.
static func save(replay: Replay, path: String) -> Error:
	if replay == null:
		return ERR_INVALID_PARAMETER
	var base := path.get_base_dir()
	if not base.is_empty() and not DirAccess.dir_exists_absolute(base):
		var made := DirAccess.make_dir_recursive_absolute(base)
		if made != OK:
			push_error("Could not make the folder %s: %s" % [base, error_string(made)])
			return made
	var error := SafeWrite.write_text(path, ReplayWriter.write(replay))
	if error != OK:
		push_error("Could not save the replay %s: %s" % [path, error_string(error)])
	return error


## {"replay": Replay} or {"error": message naming the file and the problem}.
static func read_file(path: String) -> Dictionary:
	if not FileAccess.file_exists(path):
		return {"error": "%s: there is no such file" % path}
	var file := FileAccess.open(path, FileAccess.READ)
	if file == null:
		var reason := error_string(FileAccess.get_open_error())
		return {"error": "%s: the file cannot be read (%s)" % [path, reason]}
	if file.get_length() > ReplayReader.MAX_BYTES:
		return {"error": "%s: the file is larger than %d bytes" % [path, ReplayReader.MAX_BYTES]}
	var bytes := file.get_buffer(file.get_length())
	if bytes.has(0):
		return {"error": "%s: the file contains a NUL byte; a replay is plain text" % path}
	var read := ReplayReader.read(bytes.get_string_from_utf8())
	if read.has("error"):
		return {"error": "%s: %s" % [path, read["error"]]}
	return read


## {"level": BoardLevel} for the board `replay` was recorded on (same id, same content
## hash), or {"error": why not}: no such board, or its content changed since.
static func find_board(replay: Replay) -> Dictionary:
	var kind := BoardLevel.Kind.MAZE if replay.game == Replay.MAZE else BoardLevel.Kind.PACHINKO
	var changed := ""
	for root in BOARD_ROOTS:
		for loaded in BoardLoader.list_boards(kind, root):
			if loaded.level == null or loaded.level.board_id != replay.board_id:
				continue
			if replay.recorded_on(loaded.level):
				return {"level": loaded.level}
			var content := Replay.board_hash_of(loaded.level)
			changed = (
				(
					"the %s board '%s' (%s) has changed since the replay was recorded"
					% [replay.game, replay.board_id, loaded.path]
				)
				+ (
					" (board play hash %s…, the replay's %s…)"
					% [content.left(12), replay.board_hash.left(12)]
				)
			)
	if not changed.is_empty():
		return {"error": changed}
	return {
		"error":
		"there is no %s board '%s' in levels/ or user://boards/" % [replay.game, replay.board_id]
	}
