extends GutTest
## The --autoplay command once its flags are parsed: board names and a missing board.


func test_board_names_resolve_to_level_files() -> void:
	assert_eq(AutoplayCli.resolve_board_path("maze", "classic"), "res://levels/maze/classic.board")
	assert_eq(AutoplayCli.resolve_board_path("pachinko", "res://x/y.tres"), "res://x/y.tres")


func test_a_board_that_cannot_load_exits_2() -> void:
	var values := {"autoplay": "maze", "board": "no_such_board", "seed": 1, "hard": false}
	assert_eq(AutoplayCli.run(values), AutoplayCli.EXIT_BAD_BOARD)
	assert_eq(AutoplayCli.EXIT_BAD_BOARD, 2)


func test_the_other_games_board_exits_2_with_ok_false() -> void:
	var values := {
		"autoplay": "pachinko",
		"board": "res://levels/maze/classic.board",
		"seed": 1,
		"handle": 60,
		"seconds": 1.0
	}
	assert_eq(AutoplayCli.run(values), AutoplayCli.EXIT_BAD_BOARD)
	var report := AutoplayCli.play(values)
	assert_false(report["ok"])
	assert_eq(
		report["error"], "res://levels/maze/classic.board: a maze board, not a pachinko board"
	)
	values = {"autoplay": "maze", "board": "res://levels/pachinko/classic.board", "seed": 1}
	values.merge({"hard": false, "seconds": 1.0})
	assert_eq(AutoplayCli.run(values), AutoplayCli.EXIT_BAD_BOARD)


func test_a_game_that_refuses_to_start_exits_2() -> void:
	var values := {"autoplay": "pachinko", "board": "classic", "seed": 1, "handle": 500}
	values["seconds"] = 1.0
	assert_eq(AutoplayCli.run(values), AutoplayCli.EXIT_BAD_BOARD)
	assert_push_error("handle")
	assert_string_contains(str(AutoplayCli.play(values).get("error")), "0 to 100")
	assert_push_error("handle")
