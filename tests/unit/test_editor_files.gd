extends GutTest
## New boards, the play-test request and saving a board to its own file.

const NewBoard := preload("res://addons/board_editor/core/new_board.gd")
const PlayTest := preload("res://addons/board_editor/ui/play_test.gd")
const BoardFiles := preload("res://addons/board_editor/ui/board_files.gd")

const SCRATCH := "user://test_editor_files_board.board"
## The game only plays boards from levels/: a play-test board has to be saved there.
const SCRATCH_LEVEL := "res://levels/maze/test_editor_files_scratch.board"


func after_each() -> void:
	for path in [SCRATCH, SCRATCH_LEVEL, PlayTest.REQUEST_PATH]:
		if FileAccess.file_exists(path):
			DirAccess.remove_absolute(path)


func test_new_boards_are_playable_starting_points() -> void:
	var maze := NewBoard.make(BoardLevel.Kind.MAZE)
	assert_true(maze.is_maze())
	assert_eq(BoardValidator.errors(maze).size(), 0, "a new maze has no errors")
	assert_eq(maze.ball_starts.size(), 4)
	assert_eq(maze.walls.size(), 8, "four border walls")
	var machine := NewBoard.make(BoardLevel.Kind.PACHINKO)
	assert_true(machine.is_pachinko())
	assert_eq(BoardValidator.errors(machine).size(), 0, "a new machine has no errors")


func test_free_path_never_overwrites_a_board() -> void:
	var level := NewBoard.make(BoardLevel.Kind.MAZE)
	level.board_id = "maze_classic"
	assert_eq(NewBoard.free_path(level), "res://levels/maze/classic_2.board")
	level.board_id = "maze_Fresh Idea"
	assert_eq(NewBoard.free_path(level), "res://levels/maze/fresh_idea.board")


func test_play_test_request_names_the_saved_board() -> void:
	var level := NewBoard.make(BoardLevel.Kind.MAZE)
	assert_eq(ResourceSaver.save(level, SCRATCH_LEVEL), OK)
	level.take_over_path(SCRATCH_LEVEL)
	assert_eq(PlayTest.write_request(level), "")
	var request := PlaytestRequest.read(PlayTest.REQUEST_PATH)
	assert_eq(request, {"board": SCRATCH_LEVEL, "kind": "maze", "problem": ""})


func test_play_test_refuses_a_board_the_game_would_not_play() -> void:
	var level := NewBoard.make(BoardLevel.Kind.MAZE)
	assert_eq(ResourceSaver.save(level, SCRATCH), OK)
	level.take_over_path(SCRATCH)
	assert_string_contains(PlayTest.write_request(level), "res://levels/maze/<name>.board")
	assert_false(FileAccess.file_exists(PlayTest.REQUEST_PATH), "no request the game would drop")


func test_play_test_refuses_boards_without_a_file_or_with_errors() -> void:
	var level := NewBoard.make(BoardLevel.Kind.MAZE)
	assert_string_contains(PlayTest.write_request(level), "own .board file")
	level.take_over_path(SCRATCH)
	level.goal_radius = -1.0
	assert_string_contains(PlayTest.run(level), "error")
	assert_false(FileAccess.file_exists(PlayTest.REQUEST_PATH), "no request for a broken board")


func test_save_all_writes_edits_to_the_board_file() -> void:
	var level := NewBoard.make(BoardLevel.Kind.MAZE)
	assert_eq(ResourceSaver.save(level, SCRATCH), OK)
	level.take_over_path(SCRATCH)
	level.holes = PackedVector2Array([Vector2(52.5, 52.5)])
	BoardFiles.save_all([level] as Array[BoardLevel])
	var saved := ResourceLoader.load(SCRATCH, "", ResourceLoader.CACHE_MODE_IGNORE) as BoardLevel
	assert_eq(saved.holes, PackedVector2Array([Vector2(52.5, 52.5)]))


func test_save_as_names_the_file_after_the_board() -> void:
	assert_eq(BoardFiles.file_id_for("  Tulip Garden 2! "), "tulip_garden_2")
	assert_eq(BoardFiles.file_id_for("Été"), "t", "letters outside a-z are dropped")
	var pachinko := BoardLevel.Kind.PACHINKO
	assert_eq(BoardFiles.path_for(pachinko, "rain"), "res://levels/pachinko/rain.board")
	assert_eq(BoardFiles.new_file_problem(pachinko, "fresh_board_x"), "")
	assert_string_contains(BoardFiles.new_file_problem(pachinko, "classic"), "already exists")
	assert_string_contains(BoardFiles.new_file_problem(pachinko, "../up"), "not allowed")
	assert_string_contains(BoardFiles.new_file_problem(pachinko, ""), "name")


func test_save_as_writes_the_named_board_file() -> void:
	var level := NewBoard.make(BoardLevel.Kind.MAZE)
	var path := BoardFiles.path_for(level.kind, "zz_save_as_test")
	level.display_name = "Save-as test"
	var said := BoardFiles.save_as_file(level, "zz_save_as_test")
	assert_string_contains(said, path)
	assert_eq(level.resource_path, path, "the board's home is the new file")
	var loaded := BoardLoader.load_board(path)
	assert_eq(loaded.error, "")
	assert_eq(loaded.level.display_name if loaded.level != null else "", "Save-as test")
	assert_string_contains(BoardFiles.save_as_file(level, "zz_save_as_test"), "already exists")
	level.take_over_path("")
	DirAccess.remove_absolute(path)
	DirAccess.remove_absolute(path + ".uid")
