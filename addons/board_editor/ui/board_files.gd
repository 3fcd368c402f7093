@tool
extends RefCounted
## Writing boards to disk from the editor: saving edited board files with the scene, and
## giving a board that lives inside a scene its own file in levels/.

## Longest file id (the part before .board) a new board may have.
const MAX_ID_LENGTH := 48


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


## A file id made from a board name: "Tulip Garden 2" -> "tulip_garden_2".
static func file_id_for(display_name: String) -> String:
	var id := ""
	for character in display_name.strip_edges().to_lower():
		var letter := character >= "a" and character <= "z"
		var digit := character >= "0" and character <= "9"
		if letter or digit:
			id += character
		elif not id.is_empty() and not id.ends_with("_"):
			id += "_"
	return id.trim_suffix("_").left(MAX_ID_LENGTH)


## The level file for a board of `kind` with file id `id`.
static func path_for(kind: int, id: String) -> String:
	return "res://levels/%s/%s.board" % [BoardLevel.kind_name(kind), id]


## "" when `id` can name a new level file of `kind`, else what is wrong with it.
static func new_file_problem(kind: int, id: String) -> String:
	if id.is_empty():
		return "Give the file a name."
	if id.length() > MAX_ID_LENGTH:
		return "The file name is longer than %d characters." % MAX_ID_LENGTH
	for character in id:
		var ok := (character >= "a" and character <= "z") or (character >= "0" and character <= "9")
		if not ok and character != "_":
			return "Use only a-z, 0-9 and _ in the file name ('%s' is not allowed)." % character
	var path := path_for(kind, id)
	if FileAccess.file_exists(path) or ResourceLoader.exists(path):
		return "%s already exists; pick another name." % path.get_file()
	return ""


## The board id a board saved as levels/<kind>/<file_id>.board gets ("pachinko_tulips").
static func board_id_for(kind: int, file_id: String) -> String:
	return "%s_%s" % [BoardLevel.kind_name(kind), file_id]


## Writes `level` to levels/<kind>/<file_id>.board, which becomes its home; returns a
## sentence for the dock. (The plugin names the board first, as one undoable step.)
static func save_as_file(level: BoardLevel, file_id: String) -> String:
	var problem := new_file_problem(level.kind, file_id)
	if not problem.is_empty():
		return "Not saved: " + problem
	var path := path_for(level.kind, file_id)
	var error := ResourceSaver.save(level, path)
	if error != OK:
		return "Could not write %s (%s)." % [path, error_string(error)]
	level.take_over_path(path)
	if Engine.is_editor_hint():
		EditorInterface.get_resource_filesystem().update_file(path)
		EditorInterface.mark_scene_as_unsaved()
	return "Saved the board to %s; save the scene to keep the link." % path
