extends GutTest
## The board tool's maze generator: one action replaces the maze's layout and one undo puts
## the old board back exactly; the toolbar button commits it through the edit session.

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const GenerateMazeAction := preload("res://addons/board_editor/generator/generate_maze_action.gd")
const MazeGeneratorButton := preload("res://addons/board_editor/generator/maze_generator_button.gd")


func _classic() -> BoardLevel:
	return BoardLoader.load_board("res://levels/maze/classic.board").level


func _settings(values: Dictionary) -> MazeGenSettings:
	var settings := MazeGenSettings.new()
	settings.read(values)
	return settings


func test_one_undo_step_replaces_and_restores_the_board() -> void:
	var level := _classic()
	var before := BoardTextWriter.write(level)
	var session := BoardEditSession.new(level)
	var made := MazeGenerator.generate(_settings({"cols": 14, "rows": 11, "seed": 4}))
	var generated: BoardLevel = made["level"]
	session.commit(GenerateMazeAction.new(level, generated))
	var after := BoardTextWriter.write(level)
	assert_ne(after, before)
	assert_eq(level.grid_cols, 14)
	assert_eq(level.size, Vector2(14, 11) * 35.0)
	assert_eq(level.board_id, "maze_classic", "the board keeps its id and name")
	assert_true(level.medal_times_easy.is_empty(), "old medal times do not fit a new maze")
	assert_false(
		BoardValidator.validate(level).any(func(i: BoardIssue) -> bool: return i.is_error())
	)
	assert_eq(session.history.names(), PackedStringArray(["Generate maze"]), "one step")
	assert_true(session.history.undo())
	# every item and id comes back; the id counters never go back (ItemIds), so no id the
	# generated maze used is handed out again
	assert_eq(_without_counters(BoardTextWriter.write(level)), before, "undo puts every item back")
	assert_false(level.next_ids.is_empty(), "the counters stay past the generated ids")
	assert_true(session.history.redo())
	assert_eq(BoardTextWriter.write(level), after, "redo lands the same maze")


# A board file's text without its id counters line (`{"next_ids": ...}`).
func _without_counters(text: String) -> String:
	var kept := PackedStringArray()
	for line in text.split("\n"):
		if not line.begins_with('{"next_ids"'):
			kept.append(line)
	return "\n".join(kept)


func test_bad_requests_are_refused_without_touching_the_board() -> void:
	var pachinko := BoardLoader.load_board("res://levels/pachinko/classic.board").level
	var before := BoardTextWriter.write(pachinko)
	var session := BoardEditSession.new(pachinko)
	var button: MazeGeneratorButton = autofree(MazeGeneratorButton.new())
	button.bind(session)
	assert_string_contains(button.generate(), "maze boards only")
	assert_eq(BoardTextWriter.write(pachinko), before)
	assert_eq(session.history.names().size(), 0, "nothing committed")
	assert_string_contains(str(MazeGenerator.generate(_settings({"cols": 1}))["error"]), "rows")


func test_the_toolbar_button_generates_through_the_session() -> void:
	var level := _classic()
	var session := BoardEditSession.new(level)
	var button: MazeGeneratorButton = autofree(MazeGeneratorButton.new())
	button.bind(session)
	assert_true(button.visible, "shown for a maze")
	var settings := button.settings()
	assert_eq(settings.id, "classic")
	assert_eq(button.generate(), "")
	assert_eq(session.history.names().size(), 1)
	var pachinko_session := BoardEditSession.new(BoardLevel.new())
	button.bind(pachinko_session)
	assert_false(button.visible, "hidden for a pachinko board")
