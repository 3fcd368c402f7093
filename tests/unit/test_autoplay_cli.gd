extends GutTest
## The --autoplay command once its flags are parsed: board names and a missing board.

const AutoplayCli := preload("res://scripts/app/autoplay_cli.gd")


func test_board_names_resolve_to_level_files() -> void:
	assert_eq(AutoplayCli.resolve_board_path("maze", "classic"), "res://levels/maze/classic.board")
	assert_eq(AutoplayCli.resolve_board_path("pachinko", "res://x/y.tres"), "res://x/y.tres")


func test_a_board_that_cannot_load_exits_2() -> void:
	var values := {"autoplay": "maze", "board": "no_such_board", "seed": 1, "hard": false}
	assert_eq(AutoplayCli.run(values), AutoplayCli.EXIT_BAD_BOARD)
	assert_eq(AutoplayCli.EXIT_BAD_BOARD, 2)
