extends GutTest
## The four original boards: valid, and exactly what the editor's actions build (the files
## are the output of tools/make_original_boards.gd, not hand edits).

const MakeOriginalBoards := preload("res://tools/make_original_boards.gd")
const MakeOriginalMazes := preload("res://tools/make_original_mazes.gd")

const FILES := {
	"res://levels/pachinko/tulips.board": [MakeOriginalBoards, "make_tulips"],
	"res://levels/pachinko/windmills.board": [MakeOriginalBoards, "make_windmills"],
	"res://levels/maze/catacombs.board": [MakeOriginalMazes, "make_catacombs"],
	"res://levels/maze/courtyards.board": [MakeOriginalMazes, "make_courtyards"],
}


func test_every_original_board_loads_without_errors() -> void:
	for path: String in FILES:
		var result := BoardLoader.load_board(path)
		assert_not_null(result.level, "%s loads (%s)" % [path, result.error])
		if result.level != null:
			assert_eq(BoardValidator.errors(result.level).size(), 0, path + " has no errors")


func test_files_match_what_the_editor_actions_build() -> void:
	for path: String in FILES:
		var recipe: Array = FILES[path]
		var built: BoardLevel = (recipe[0] as Script).call(recipe[1])
		# The file is the built board in its saved form (coordinates rounded to 0.01 px),
		# plus the medal times measured later by tools/maze_pilot_table.gd.
		var saved := BoardLoader.load_board(path).level
		built.medal_times_easy = saved.medal_times_easy
		built.medal_times_hard = saved.medal_times_hard
		assert_eq(FileAccess.get_file_as_string(path), BoardTextWriter.write(built), path)


func test_boards_differ_in_character() -> void:
	var tulips := BoardLoader.load_board("res://levels/pachinko/tulips.board").level
	var windmills := BoardLoader.load_board("res://levels/pachinko/windmills.board").level
	assert_gt(tulips.pins.size(), windmills.pins.size() * 2, "tulips is the dense one")
	assert_gt(tulips.pockets.size(), windmills.pockets.size())
	var catacombs := BoardLoader.load_board("res://levels/maze/catacombs.board").level
	assert_eq(Vector2i(catacombs.grid_cols, catacombs.grid_rows), Vector2i(12, 9))
	assert_gt(catacombs.holes.size(), 0)
