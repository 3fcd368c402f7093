extends GutTest
## The strengths that have paid this game (PayingStrengths): each ball counts in the band of
## the power it flew at, with what it paid back; a band shows its return once it has had
## MIN_SHOTS balls, and the best band is the one that paid most per ball.


func test_each_ball_counts_in_its_band_with_what_it_paid() -> void:
	var tally := PayingStrengths.new()
	assert_eq(tally.best_band(), -1, "nothing paid yet")
	for id in 4:
		tally.note_launch(id, 31.0)  # band 3
	for id in range(4, 8):
		tally.note_launch(id, 78.0)  # band 7
	tally.note_paid(1, 6)
	tally.note_paid(5, 2)
	tally.note_paid(99, 50)  # a ball never launched
	assert_eq(tally.shots(3), 4)
	assert_almost_eq(tally.return_of(3), 1.5, 0.001, "6 balls back for 4 shots")
	assert_almost_eq(tally.return_of(7), 0.5, 0.001)
	assert_eq(tally.best_band(), 3)


func test_a_band_with_too_few_shots_says_nothing_yet() -> void:
	var tally := PayingStrengths.new()
	tally.note_launch(1, 100.0)
	tally.note_paid(1, 10)
	assert_eq(
		PayingStrengths.band_of(100.0), PayingStrengths.BANDS - 1, "full power is the top band"
	)
	assert_eq(tally.return_of(PayingStrengths.BANDS - 1), 0.0, "one lucky ball is not a pattern")
	assert_eq(tally.best_band(), -1)


func test_the_game_lights_the_bands_its_balls_paid_from() -> void:
	App.request_board("pachinko", "res://levels/pachinko/classic.board")
	var game := (
		(load("res://scenes/pachinko/pachinko_game.tscn") as PackedScene).instantiate()
		as PachinkoGame
	)
	add_child_autofree(game)
	await wait_process_frames(1)
	var rules := game.rules
	rules.start_game()
	var ids: Array[int] = []
	rules.ball_launched.connect(func(id: int, _p: float, _s: float) -> void: ids.append(id))
	for shot in 3:
		rules.fire(42.0)
		rules.advance(0.5)
	assert_eq(game.paying_strengths().shots(4), 3, "three balls at 42 in the 40s band")
	rules.ball_won.emit(ids[0], 0, 9, Vector2.ZERO)
	assert_eq(game.paying_strengths().best_band(), 4, "its pay lights that band")
	game.restart()
	assert_eq(game.paying_strengths().shots(4), 0, "a new game starts afresh")
