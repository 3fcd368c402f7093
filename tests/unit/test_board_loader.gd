extends GutTest
## Broken board files are refused with a message naming the file and the problem; the
## others keep loading. Old files are upgraded.

const LegacyBoardLoader := preload("res://tools/legacy_boards/legacy_board_loader.gd")
const BoardUpgrader := preload("res://tools/legacy_boards/board_upgrader.gd")
const DIR := "res://tests/fixtures/boards/"
## Fixture → words its refusal must contain.
const BROKEN := {
	"broken_unparsable": "never closed",
	"broken_format": "resource format 9",
	"broken_unclosed": "'display_name' is never closed",
	"broken_garbage": "not a Godot text resource",
	"broken_not_board": "PocketSpec, not a BoardLevel",
	"broken_texture": "GradientTexture1D, not a BoardLevel",
	"broken_wrong_type": "'ball_radius' should be float",
	"broken_wrong_array_type": "'pin_pocket' should be PackedInt32Array",
	"broken_nan": "not a number",
	"broken_pin_outside": "outside the ring",
	"broken_zero_wall": "zero length",
	"broken_version": "unknown version 99",
	"broken_missing_fields": "ball radius must be positive",
	"broken_unknown_field": "no field 'flipper_colour'",
	"broken_outside_script": "res://scenes/app/app.gd",
	"broken_embedded_script": "embeds a GDScript",
	"broken_array_mismatch": "pin lists disagree",
	"v0_broken_pockets": "upgrading from version 0",
}


func test_each_broken_file_is_refused_with_its_problem() -> void:
	for name: String in BROKEN:
		var path := DIR + name + ".tres"
		var loaded := LegacyBoardLoader.load_board(path)
		assert_null(loaded.level, name)
		assert_false(loaded.ok(), name)
		assert_string_contains(loaded.error, path, false)
		var expected: String = BROKEN[name]
		assert_string_contains(loaded.error, expected, false)


func test_missing_file_and_untrusted_places_are_refused() -> void:
	var missing := LegacyBoardLoader.load_board(DIR + "no_such_board.tres")
	assert_string_contains(missing.error, "does not exist")
	var outside := LegacyBoardLoader.load_board("user://some_board.tres")
	assert_string_contains(outside.error, "only res://")
	var binary := LegacyBoardLoader.load_board(DIR + "tiny_pachinko.res")
	assert_string_contains(binary.error, ".tres")
	assert_string_contains(LegacyBoardLoader.load_board("").error, "only res://")


func test_good_fixtures_load() -> void:
	for name: String in ["tiny_pachinko", "tiny_maze"]:
		var loaded := LegacyBoardLoader.load_board(DIR + name + ".tres")
		assert_true(loaded.ok(), loaded.error)
		assert_eq(loaded.warnings.size(), 0, name)


func test_a_broken_board_does_not_stop_the_others() -> void:
	var results := BoardLoader.list_boards(BoardLevel.Kind.PACHINKO, DIR + "catalog")
	var names: Array[String] = []
	var good := 0
	for loaded in results:
		names.append(loaded.path.get_file())
		good += 1 if loaded.ok() else 0
	assert_eq(
		names, ["a_good.board", "b_broken.board", "c_maze_in_wrong_folder.board", "d_good.board"]
	)
	assert_eq(good, 2)
	assert_string_contains(results[2].error, "not a pachinko board")
	var mazes := BoardLoader.list_boards(BoardLevel.Kind.MAZE, DIR + "catalog")
	assert_eq(mazes.size(), 1)
	assert_true(mazes[0].ok(), mazes[0].error)


func test_version_0_pachinko_is_upgraded() -> void:
	var loaded := LegacyBoardLoader.load_board(DIR + "v0_pachinko.tres")
	assert_true(loaded.ok(), loaded.error)
	var level := loaded.level
	assert_eq(level.version, BoardLevel.CURRENT_VERSION)
	assert_eq([level.rail_start_deg, level.rail_end_deg], [40.0, -105.0])
	assert_eq([level.gutter_start_deg, level.gutter_end_deg], [60.0, 120.0])
	assert_eq(level.pockets.size(), 1)
	var spec: PocketSpec = level.pockets[0]
	assert_eq(spec.position, Vector2(150, 160))
	assert_eq([spec.width, spec.depth, spec.payout], [22.0, 24.0, 4])
	assert_true(level.legacy_fields.is_empty())


func test_version_0_maze_walls_become_pixel_segments() -> void:
	var old := LegacyBoardLoader.load_board(DIR + "v0_maze.tres")
	var current := LegacyBoardLoader.load_board(DIR + "tiny_maze.tres")
	assert_true(old.ok(), old.error)
	assert_eq(old.level.walls, current.level.walls)
	assert_eq(old.level.version, BoardLevel.CURRENT_VERSION)


func test_upgrader_refuses_unknown_versions_and_leftover_fields() -> void:
	var level := BoardLevel.new()
	assert_string_contains(BoardUpgrader.upgrade(level, 7), "unknown version 7")
	level.legacy_fields["mystery"] = 1
	assert_string_contains(BoardUpgrader.upgrade(level, 1), "mystery")
