class_name BoardLoader
extends RefCounted
## Loads boards safely: only res:// files, checked before and after the engine parses them,
## upgraded from older versions and validated. A broken board never stops the others.

const FileCheck := preload("res://scripts/loading/board_file_check.gd")
const LEVELS_DIR := "res://levels"
## At most this many validator errors are quoted in a refusal message.
const ERRORS_QUOTED := 3


## Loads, upgrades and validates one board. The result holds the level or an error message
## naming the file and the problem.
static func load_board(path: String) -> BoardLoadResult:
	var result := BoardLoadResult.new()
	result.path = path
	if not path.begins_with("res://"):
		return _fail(result, "only res:// board files are trusted to load")
	if not path.ends_with(".tres"):
		return _fail(result, "a board file must be a text resource (.tres)")
	var checked := {"error": "", "version": -1}
	if FileAccess.file_exists(path):
		checked = FileCheck.check(path)
	elif not FileAccess.file_exists(path + ".remap"):
		return _fail(result, "the file does not exist")
	# else: an exported build converted our own shipped file to binary; it is trusted as is.
	var problem: String = checked["error"]
	if not problem.is_empty():
		return _fail(result, problem)
	var resource: Resource = ResourceLoader.load(path, "", ResourceLoader.CACHE_MODE_REUSE)
	if resource == null:
		return _fail(result, "the file could not be parsed as a resource")
	if not resource is BoardLevel:
		return _fail(result, "the file is not a BoardLevel")
	var level := resource as BoardLevel
	var from_version: int = checked["version"] if checked["version"] >= 0 else level.version
	var upgrade_problem := BoardUpgrader.upgrade(level, from_version)
	if not upgrade_problem.is_empty():
		return _fail(result, upgrade_problem)
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


## Every board of a kind (BoardLevel.Kind), sorted by file name: a result per `.tres` file
## in `<root>/<kind>/` (root: levels/), broken ones included (with their error).
static func list_boards(kind: int, root: String = LEVELS_DIR) -> Array[BoardLoadResult]:
	var results: Array[BoardLoadResult] = []
	var dir_path := "%s/%s" % [root, BoardLevel.kind_name(kind)]
	var names: Array[String] = []
	for file_name in DirAccess.get_files_at(dir_path):
		# Exported builds list remapped files; the loader takes the original name.
		var plain := file_name.trim_suffix(".remap")
		if plain.ends_with(".tres") and not names.has(plain):
			names.append(plain)
	names.sort()
	for file_name in names:
		var loaded := load_board("%s/%s" % [dir_path, file_name])
		if loaded.level != null and loaded.level.kind != kind:
			loaded = _fail(loaded, "the board is not a %s board" % BoardLevel.kind_name(kind))
		results.append(loaded)
	return results


static func _fail(result: BoardLoadResult, problem: String) -> BoardLoadResult:
	result.level = null
	result.warnings.clear()
	result.error = "%s: %s" % [result.path, problem]
	return result
