@tool
extends RefCounted
## Writing boards to disk from the editor: saving edited board files with the scene, and
## giving a board that lives inside a scene its own file in levels/.

const NewBoard := preload("res://addons/board_editor/core/new_board.gd")


## Saves every board in `levels` that has its own file (boards built into a scene are
## saved with the scene).
static func save_all(levels: Array[BoardLevel]) -> void:
	for level in levels:
		var path := level.resource_path
		if path.is_empty() or path.contains("::"):
			continue
		var error := ResourceSaver.save(level, path)
		if error != OK:
			push_error("Board editor: could not save %s (%s)." % [path, error_string(error)])


## Writes `level` to a free path in levels/<kind>/ and makes that its home; returns a
## sentence for the dock.
static func save_as_file(level: BoardLevel) -> String:
	var path := NewBoard.free_path(level)
	var error := ResourceSaver.save(level, path)
	if error != OK:
		return "Could not write %s (%s)." % [path, error_string(error)]
	level.take_over_path(path)
	if Engine.is_editor_hint():
		EditorInterface.get_resource_filesystem().update_file(path)
		EditorInterface.mark_scene_as_unsaved()
	return "Saved the board to %s; save the scene to keep the link." % path
