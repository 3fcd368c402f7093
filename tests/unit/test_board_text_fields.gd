extends GutTest
## The board reader's field checks, as a designer meets them: each wrong field, item or
## tuning constant is refused with a message naming it, and what is allowed loads.

const Reader := preload("res://scripts/loading/board_text_reader.gd")
const PACHINKO := "res://levels/pachinko/classic.board"
const MAZE := "res://levels/maze/classic.board"


# The lines of a shipped board, with the lines holding any of `drop` left out.
func _lines(path: String, drop: Array[String] = []) -> PackedStringArray:
	var kept := PackedStringArray()
	for line in FileAccess.get_file_as_string(path).split("\n"):
		var dropped := false
		for text in drop:
			dropped = dropped or line.contains(text)
		if not dropped and not line.strip_edges().is_empty():
			kept.append(line)
	return kept


func _error(path: String, extra: Array[String], drop: Array[String] = []) -> String:
	var lines := _lines(path, drop)
	lines.append_array(PackedStringArray(extra))
	return str(Reader.read("\n".join(lines)).get("error", ""))


func _level(path: String, extra: Array[String], drop: Array[String] = []) -> BoardLevel:
	var lines := _lines(path, drop)
	lines.append_array(PackedStringArray(extra))
	return Reader.read("\n".join(lines)).get("level")


func test_a_pin_naming_a_pocket_the_board_lacks_is_refused_by_pin_and_pocket() -> void:
	var pin := '{"pin": {"id": 900, "x": 300, "y": 120, "pocket": %d}}'
	assert_eq(
		_error(PACHINKO, [pin % 150]), "pin 900 names pocket 150; the board has 5 pockets (0 to 4)"
	)
	assert_eq(
		_error(PACHINKO, [pin % 5]),
		"pin 900 names pocket 5; the board has 5 pockets (0 to 4)",
		"pockets count from 0: 5 is one past the last"
	)
	var pins := 0
	for line in _lines(PACHINKO):
		pins += 1 if line.begins_with('{"pin":') else 0
	var no_id := '{"pin": {"x": 300, "y": 120, "pocket": 7}}'
	assert_eq(
		_error(PACHINKO, [no_id]),
		"pins item %d names pocket 7; the board has 5 pockets (0 to 4)" % (pins + 1),
		"a pin without an id is named by its place in the list"
	)
	assert_eq(
		_error(PACHINKO, [pin % 3], ['{"pocket"']),
		"pin 900 names pocket 3; the board has no pockets"
	)


func test_a_pin_of_an_older_file_naming_a_real_pocket_still_loads() -> void:
	var level := _level(PACHINKO, ['{"pin": {"id": 900, "x": 300, "y": 120, "pocket": 4}}'])
	assert_not_null(level, "pocket 4 of 5 is the last pocket")
	var first := _level(PACHINKO, ['{"pin": {"id": 900, "x": 300, "y": 120, "pocket": 0}}'])
	assert_not_null(first, "pocket 0 is the first")
