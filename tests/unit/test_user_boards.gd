extends GutTest
## My boards as files: import only what the loader and validator accept (a refused file writes
## nothing), clashing names get new ones, export is byte for byte, delete touches only the
## player's own file, and a player's board never takes a shipped board's place or id.

const ROOT := "user://test_user_boards"
const OUT := "user://test_user_boards_out"
const HOSTILE := "res://tests/fixtures/hostile_boards/pachinko"
const CLASSIC := "res://levels/pachinko/classic.board"
const MAZE := "res://levels/maze/classic.board"
const MARKER := "user://hostile_payload_ran.txt"


func before_each() -> void:
	for folder: String in [ROOT, OUT]:
		_remove_tree(folder)
	DirAccess.make_dir_recursive_absolute(OUT)


func after_all() -> void:
	for folder: String in [ROOT, OUT]:
		_remove_tree(folder)


func _roots() -> Array[String]:
	var roots: Array[String] = [ROOT + "/"]
	return roots


## The file at `res_path` as a plain file outside the project, as a player would pick it.
func _outside(res_path: String, file_name: String) -> String:
	var target := ProjectSettings.globalize_path(OUT).path_join(file_name)
	var file := FileAccess.open(target, FileAccess.WRITE)
	file.store_buffer(FileAccess.get_file_as_bytes(res_path))
	file.close()
	return target


func _files_under(folder: String) -> PackedStringArray:
	var found := PackedStringArray()
	if not DirAccess.dir_exists_absolute(folder):
		return found
	for sub in DirAccess.get_directories_at(folder):
		found.append_array(_files_under(folder.path_join(sub)))
	for file_name in DirAccess.get_files_at(folder):
		found.append(folder.path_join(file_name))
	return found


func test_a_valid_import_is_listed_and_playable() -> void:
	var outcome := UserBoards.import_file(_outside(CLASSIC, "My Great Board!.board"), ROOT)
	assert_false(outcome.has("error"), str(outcome.get("error", "")))
	assert_eq(outcome["path"], ROOT + "/pachinko/my_great_board_.board")
	var listed := BoardLoader.list_boards(BoardLevel.Kind.PACHINKO, ROOT)
	assert_eq(listed.size(), 1)
	assert_true(listed[0].ok(), listed[0].error)
	var rules := PachinkoRules.new(listed[0].level, 1)
	assert_not_null(rules, "the imported board builds a game")
	assert_eq(
		FileAccess.get_file_as_bytes(outcome["path"]),
		FileAccess.get_file_as_bytes(CLASSIC),
		"the file is copied as it is"
	)


func test_a_maze_board_goes_to_the_maze_folder() -> void:
	var outcome := UserBoards.import_file(_outside(MAZE, "labyrinth.board"), ROOT)
	assert_eq(outcome.get("path"), ROOT + "/maze/labyrinth.board")
	var listed := BoardLoader.list_boards(BoardLevel.Kind.MAZE, ROOT)
	assert_true(listed[0].ok(), listed[0].error)
	assert_not_null(MazeRules.new(listed[0].level, false))


func test_every_hostile_file_is_refused_and_nothing_is_written() -> void:
	DirAccess.remove_absolute(ProjectSettings.globalize_path(MARKER))
	var refused := 0
	for file_name in DirAccess.get_files_at(HOSTILE):
		var source := _outside("%s/%s" % [HOSTILE, file_name], file_name)
		var direct := BoardLoader.load_board("%s/%s" % [HOSTILE, file_name], [HOSTILE + "/"])
		var outcome := UserBoards.import_file(source, ROOT)
		assert_eq(
			outcome.has("error"), not direct.ok(), "import agrees with the loader: " + file_name
		)
		if outcome.has("error"):
			refused += 1
			assert_string_contains(str(outcome["error"]), file_name, "the message names the file")
	assert_gt(refused, 15, "the hostile corpus is refused")
	var written := _files_under(ROOT)
	var accepted := DirAccess.get_files_at(HOSTILE).size() - refused
	assert_eq(written.size(), accepted, "only accepted boards were copied: %s" % str(written))
	assert_false(FileAccess.file_exists(MARKER), "no payload ran")


func test_not_a_board_file_or_missing_is_refused() -> void:
	var text := _outside(CLASSIC, "classic.txt")
	assert_string_contains(str(UserBoards.import_file(text, ROOT)["error"]), "only .board files")
	var missing := UserBoards.import_file("/no/such/place/x.board", ROOT)
	assert_string_contains(str(missing["error"]), "x.board: the file could not be read")
	assert_eq(_files_under(ROOT).size(), 0)


func test_clashing_names_get_new_ones() -> void:
	var source := _outside(CLASSIC, "classic.board")
	var paths := PackedStringArray()
	for time in 3:
		paths.append(str(UserBoards.import_file(source, ROOT)["path"]))
	assert_eq(
		paths,
		PackedStringArray(
			[
				ROOT + "/pachinko/classic.board",
				ROOT + "/pachinko/classic_2.board",
				ROOT + "/pachinko/classic_3.board",
			]
		)
	)
	assert_eq(UserBoards.free_path(ROOT + "/pachinko", "other"), ROOT + "/pachinko/other.board")


func test_a_players_board_with_a_shipped_id_keeps_its_own_place_and_id() -> void:
	var before := FileAccess.get_md5(CLASSIC)
	var outcome := UserBoards.import_file(_outside(CLASSIC, "classic.board"), ROOT)
	var mine: BoardLoadResult = outcome["result"]
	var shipped := BoardLoader.load_board(CLASSIC)
	assert_true(mine.ok(), mine.error)
	assert_ne(mine.path, shipped.path)
	assert_eq(mine.level.board_id, "my:classic", "best results never mix with the shipped one")
	assert_eq(shipped.level.board_id, "pachinko_classic")
	assert_eq(FileAccess.get_md5(CLASSIC), before, "the shipped file is untouched")


func test_delete_removes_only_the_players_file() -> void:
	var first: String = UserBoards.import_file(_outside(CLASSIC, "one.board"), ROOT)["path"]
	var second: String = UserBoards.import_file(_outside(CLASSIC, "two.board"), ROOT)["path"]
	assert_eq(UserBoards.delete_file(first, ROOT), OK)
	assert_false(FileAccess.file_exists(first))
	assert_true(FileAccess.file_exists(second), "the other board stays")
	assert_eq(UserBoards.delete_file(CLASSIC, ROOT), ERR_FILE_BAD_PATH, "never a shipped board")
	assert_eq(UserBoards.delete_file(CLASSIC), ERR_FILE_BAD_PATH)
	assert_eq(
		UserBoards.delete_file(ROOT + "/pachinko/../pachinko/two.board", ROOT), ERR_FILE_BAD_PATH
	)
	assert_eq(UserBoards.delete_file(ROOT + "/two.board", ROOT), ERR_FILE_BAD_PATH)
	assert_true(FileAccess.file_exists(CLASSIC))
	assert_true(FileAccess.file_exists(second))


func test_export_round_trips_byte_identical() -> void:
	var target := ProjectSettings.globalize_path(OUT).path_join("shared")
	assert_eq(UserBoards.export_file(CLASSIC, target), OK)
	assert_eq(
		FileAccess.get_file_as_bytes(target + ".board"),
		FileAccess.get_file_as_bytes(CLASSIC),
		"the exported file is the board's file, byte for byte"
	)
	var back := UserBoards.import_file(target + ".board", ROOT)
	assert_eq(FileAccess.get_file_as_bytes(back["path"]), FileAccess.get_file_as_bytes(CLASSIC))
	var again := ProjectSettings.globalize_path(OUT).path_join("again.board")
	assert_eq(UserBoards.export_file(back["path"], again, _roots()), OK)
	assert_eq(FileAccess.get_file_as_bytes(again), FileAccess.get_file_as_bytes(CLASSIC))
	assert_eq(
		UserBoards.export_file("res://tests/fixtures/boards/tiny_pachinko.tres", again),
		ERR_FILE_BAD_PATH,
		"only board files in the board folders are exported"
	)


func test_safe_stem_keeps_names_plain() -> void:
	assert_eq(BoardFileName.safe_stem("My Board=1\nx"), "my_board_1_x")
	assert_eq(BoardFileName.safe_stem("..."), "board")
	assert_eq(BoardFileName.safe_stem("Ünïcode-ok"), "n_code-ok")
	assert_eq(BoardFileName.safe_stem("a".repeat(100)).length(), BoardFileName.MAX_STEM)


static func _remove_tree(path: String) -> void:
	if not DirAccess.dir_exists_absolute(path):
		return
	for folder in DirAccess.get_directories_at(path):
		_remove_tree(path.path_join(folder))
	for file_name in DirAccess.get_files_at(path):
		DirAccess.remove_absolute(path.path_join(file_name))
	DirAccess.remove_absolute(path)
