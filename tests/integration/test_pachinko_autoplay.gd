extends GutTest
## The headless autoplay: every ball accounted for after a long seeded run, and the same
## seed plays the same game.

const CLASSIC := "res://levels/pachinko/classic.board"


func _level() -> BoardLevel:
	return BoardLoader.load_board(CLASSIC).level


func test_accounting_holds_after_a_long_seeded_autoplay() -> void:
	var result := PachinkoAutoplay.run(_level(), 30.0, 1)
	assert_true(result["accounting_ok"], "cup + loaded + in play + drained + won adds up")
	assert_gt(int(result["shots"]), 25, "it kept shooting (new games included)")
	assert_gt(int(result["drained"]), 0)
	assert_eq((result["pocket_hits"] as Array).size(), _level().pockets.size())
	assert_eq(int(result["frames_simulated"]), 1800)
	var paid := 0
	var hits: Array = result["pocket_hits"]
	for i in hits.size():
		paid += int(hits[i]) * _level().pockets[i].payout
	assert_eq(paid, int(result["payouts"]), "each catch pays its own pocket's payout")


func test_the_same_seed_gives_the_same_result() -> void:
	var a := PachinkoAutoplay.run(_level(), 10.0, 7)
	var b := PachinkoAutoplay.run(_level(), 10.0, 7)
	assert_eq(JSON.stringify(a), JSON.stringify(b))
	var c := PachinkoAutoplay.run(_level(), 10.0, 8)
	assert_ne(a["state_hash"], c["state_hash"], "another seed plays differently")


func test_a_maze_board_is_refused_with_a_clear_error() -> void:
	var maze := BoardLevel.new()
	maze.kind = BoardLevel.Kind.MAZE
	var result := PachinkoAutoplay.run(maze, 1.0, 1)
	assert_push_error("a pachinko board is needed")
	assert_false(result.get("ok", true))
