extends RefCounted
## Reads a board saved in the old text-resource layout (.tres) for the converter
## (tools/convert_boards.gd) and its tests. The text is checked first (board_file_check.gd),
## then handed to Godot's resource parser, which can build objects: that is why this lives in
## tools/ (never exported, never called by the game) and reads only res:// files. Convert
## only files you trust.

const BoardFileCheck := preload("res://tools/legacy_boards/board_file_check.gd")
const BoardUpgrader := preload("res://tools/legacy_boards/board_upgrader.gd")


## The old board at `path`, upgraded to the current format and validated like a .board file.
static func load_board(path: String) -> BoardLoadResult:
	if not path.begins_with("res://") or not path.ends_with(".tres"):
		return BoardLoader.refused(
			path, "only res:// .tres files are trusted to load as old boards"
		)
	if not FileAccess.file_exists(path):
		return BoardLoader.refused(path, "the file does not exist")
	var checked := BoardFileCheck.check(path)
	var problem: String = checked["error"]
	if not problem.is_empty():
		return BoardLoader.refused(path, problem)
	var resource: Resource = ResourceLoader.load(path, "", ResourceLoader.CACHE_MODE_REUSE)
	if resource == null:
		return BoardLoader.refused(path, "the file could not be parsed as a resource")
	if not resource is BoardLevel:
		return BoardLoader.refused(path, "the file is not a BoardLevel")
	var level := resource as BoardLevel
	var from_version: int = checked["version"] if checked["version"] >= 0 else level.version
	var upgrade_problem := BoardUpgrader.upgrade(level, from_version)
	if not upgrade_problem.is_empty():
		return BoardLoader.refused(path, upgrade_problem)
	return BoardLoader.validated(path, level)
