@tool
extends RefCounted
## "New board…" in one step: a new board of a kind (NewBoard's starting point) written to
## levels/<kind>/<id>.board, and a level scene beside the shipped ones,
## scenes/boards/<kind>_<id>.tscn, whose root is a BoardNode showing it. Both are files from
## the start, so play-test and saving never have to ask where to put them.

const NewBoard := preload("res://addons/board_editor/core/new_board.gd")
const BoardFiles := preload("res://addons/board_editor/ui/board_files.gd")

## Where the level scenes live (tools/make_board_scenes.gd writes the shipped ones there).
const SCENES_DIR := "res://scenes/boards"


## The level scene for a board of `kind` with file id `file_id`.
static func scene_path_for(kind: int, file_id: String, scenes_dir := SCENES_DIR) -> String:
	return "%s/%s_%s.tscn" % [scenes_dir, BoardLevel.kind_name(kind), file_id]


## "" when a new board of `kind` may be called `file_id`, else what is wrong.
static func problem(kind: int, file_id: String, scenes_dir := SCENES_DIR) -> String:
	var wrong := BoardFiles.new_file_problem(kind, file_id)
	if not wrong.is_empty():
		return wrong
	var scene := scene_path_for(kind, file_id, scenes_dir)
	if FileAccess.file_exists(scene):
		return "%s already exists; pick another name." % scene.get_file()
	return ""


## Writes the board file and its scene; returns {"scene": path, "board": path} or
## {"error": sentence}. `board_path` may name another folder (tests); by default the
## board goes to levels/<kind>/<file_id>.board.
static func create(
	kind: int, file_id: String, display_name: String, scenes_dir := SCENES_DIR, board_path := ""
) -> Dictionary:
	var wrong := problem(kind, file_id, scenes_dir) if board_path.is_empty() else ""
	if not wrong.is_empty():
		return {"error": "Not created: " + wrong}
	var level := NewBoard.make(kind)
	level.display_name = display_name
	level.board_id = BoardFiles.board_id_for(kind, file_id)
	var path := board_path if not board_path.is_empty() else BoardFiles.path_for(kind, file_id)
	var error := ResourceSaver.save(level, path)
	if error != OK:
		return {"error": "Could not write %s (%s)." % [path, error_string(error)]}
	level.take_over_path(path)
	var scene_path := scene_path_for(kind, file_id, scenes_dir)
	var node := BoardNode.new()
	node.name = "Board"
	node.level = level
	var scene := PackedScene.new()
	error = scene.pack(node)
	if error == OK:
		error = ResourceSaver.save(scene, scene_path)
	node.free()
	if error != OK:
		DirAccess.remove_absolute(path)
		return {"error": "Could not write %s (%s)." % [scene_path, error_string(error)]}
	return {"scene": scene_path, "board": path}
