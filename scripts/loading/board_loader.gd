class_name BoardLoader
extends RefCounted
## Loads boards safely: `.board` files inside the board folders (the shipped levels/ and the
## player's user://boards/), read as data by BoardTextReader and validated. A broken board
## never stops the others. Old .tres boards are read only by the converter
## (tools/legacy_boards/legacy_board_loader.gd), never by the game.

const LEVELS_DIR := "res://levels"
## The folders boards may be loaded from: the shipped boards and the player's own.
const BOARD_ROOTS: Array[String] = ["res://levels/", "user://boards/"]
## The player's own boards ("My boards"), one folder per game kind like levels/.
const USER_DIR := "user://boards"
## A board loaded from the user folder is known as this prefix + its file name, so a player's
## board that reuses a shipped board's id never shares (or overwrites) that board's best results.
const USER_ID_PREFIX := "my:"
## At most this many validator errors are quoted in a refusal message.
const ERRORS_QUOTED := 3


## Loads, upgrades and validates one board. The result holds the level or an error message
## naming the file and the problem. `roots` are the folders the file may be in (tests pass
## their fixtures folder).
static func load_board(path: String, roots: Array[String] = BOARD_ROOTS) -> BoardLoadResult:
	var result := BoardLoadResult.new()
	result.path = path
	var outside := path_problem(path, roots)
	if not outside.is_empty():
		return _fail(result, outside)
	if path.ends_with(".tres"):
		return _fail(
			result,
			"an old board layout (.tres): convert it with tools/convert_boards.gd (see README)"
		)
	if not path.ends_with(".board"):
		return _fail(result, "a board file must be a .board file")
	var level := _read_board_file(result, path)
	if level != null and path.begins_with("user://"):
		level.board_id = USER_ID_PREFIX + BoardFileName.safe_stem(path.get_file().get_basename())
	return _finish(result, level)


## Reads and validates board text that is not (yet) in a board folder, such as a file the
## player is importing: the same reader and validator as `load_board`. `label` names the
## file in the error message.
static func load_bytes(bytes: PackedByteArray, label: String) -> BoardLoadResult:
	var result := BoardLoadResult.new()
	result.path = label
	if bytes.size() > BoardSchema.MAX_FILE_BYTES:
		return _fail(result, "the file is larger than %d bytes" % BoardSchema.MAX_FILE_BYTES)
	return _finish(result, _read_bytes(result, bytes))


## Validates a `level` built elsewhere (the legacy converter) as if it had been read from
## `path`: the same checks and messages as `load_board`.
static func validated(path: String, level: BoardLevel) -> BoardLoadResult:
	var result := BoardLoadResult.new()
	result.path = path
	return _finish(result, level)


## Why `path` cannot be loaded, in the loader's own message form ("<path>: <problem>").
static func refused(path: String, problem: String) -> BoardLoadResult:
	var result := BoardLoadResult.new()
	result.path = path
	return _fail(result, problem)


## "" when `path` is a board file inside one of BOARD_ROOTS, reached without `..` or a
## symbolic link, else why it may not be loaded.
static func path_problem(path: String, roots: Array[String] = BOARD_ROOTS) -> String:
	var root := ""
	for allowed in roots:
		if path.begins_with(allowed):
			root = allowed
	if root.is_empty():
		return "boards load only from %s" % " or ".join(roots)
	var rest := path.substr(root.length())
	if rest.is_empty() or rest.contains("\\") or rest.contains("//") or rest.contains(":"):
		return "not a plain file path inside %s" % root
	var dir := DirAccess.open(root)
	var walked := root
	for part in rest.split("/"):
		if part.is_empty() or part == "." or part == "..":
			return "the path may not contain '.' or '..' parts"
		walked = walked.path_join(part)
		if dir != null and dir.is_link(walked):
			return "%s is a symbolic link; boards must be real files inside %s" % [walked, root]
	return ""


static func _read_board_file(result: BoardLoadResult, path: String) -> BoardLevel:
	if not FileAccess.file_exists(path):
		result.error = "the file does not exist"
		return null
	var size := FileAccess.open(path, FileAccess.READ)
	if size != null and size.get_length() > BoardSchema.MAX_FILE_BYTES:
		result.error = ("the file is larger than %d bytes" % BoardSchema.MAX_FILE_BYTES)
		return null
	return _read_bytes(result, FileAccess.get_file_as_bytes(path))


static func _read_bytes(result: BoardLoadResult, bytes: PackedByteArray) -> BoardLevel:
	var read := BoardTextReader.read_bytes(bytes)
	if read.has("error"):
		result.error = read["error"]
		return null
	return read["level"]


# Validates a read level: any error refuses it, warnings ride along.
static func _finish(result: BoardLoadResult, level: BoardLevel) -> BoardLoadResult:
	if level == null:
		return _fail(result, result.error if not result.error.is_empty() else "unreadable")
	var errors: PackedStringArray = []
	for issue in BoardValidator.validate(level):
		if issue.is_error():
			errors.append(issue.message)
		else:
			result.warnings.append(issue)
	if not errors.is_empty():
		var quoted := " ".join(errors.slice(0, ERRORS_QUOTED))
		var more := errors.size() - ERRORS_QUOTED
		if more > 0:
			quoted += " (and %d more)" % more
		return _fail(result, "the board is broken: %s" % quoted)
	result.level = level
	return result


## Every board of a kind (BoardLevel.Kind), sorted by file name: a result for every file
## in `<root>/<kind>/` (root: levels/), refused ones included with their error, so a stray
## or broken file is shown to the player instead of hidden.
static func list_boards(kind: int, root: String = LEVELS_DIR) -> Array[BoardLoadResult]:
	var results: Array[BoardLoadResult] = []
	for path in list_files(kind, root):
		results.append(load_listed(path, kind, root))
	return results


## The paths of every file in `<root>/<kind>/`, sorted, less Godot's own side files.
static func list_files(kind: int, root: String = LEVELS_DIR) -> Array[String]:
	var dir_path := "%s/%s" % [root, BoardLevel.kind_name(kind)]
	var paths: Array[String] = []
	if not DirAccess.dir_exists_absolute(dir_path):
		return paths
	for file_name in DirAccess.get_files_at(dir_path):
		if file_name.begins_with(".") or file_name.get_extension() in ["uid", "import"]:
			continue
		paths.append("%s/%s" % [dir_path, file_name])
	paths.sort()
	return paths


## Loads a file found by `list_files` in `root`, refusing a board of the other kind.
static func load_listed(path: String, kind: int, root: String = LEVELS_DIR) -> BoardLoadResult:
	var roots: Array[String] = [root.trim_suffix("/") + "/"]
	var loaded := load_board(path, roots)
	if loaded.level != null and loaded.level.kind != kind:
		loaded = _fail(loaded, "the board is not a %s board" % BoardLevel.kind_name(kind))
	return loaded


static func _fail(result: BoardLoadResult, problem: String) -> BoardLoadResult:
	result.level = null
	result.warnings.clear()
	result.error = "%s: %s" % [result.path, problem]
	return result
