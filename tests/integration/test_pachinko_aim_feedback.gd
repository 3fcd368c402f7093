extends GutTest
## Two play trials could not tell what power does: while the player aims, the board shows
## the flight a shot at that power takes (LaunchPreview), and after a shot the power bar
## keeps a mark at its power so a good shot can be repeated.

const GAME := "res://scenes/pachinko/pachinko_game.tscn"


func _playing_game() -> PachinkoGame:
	var game := (load(GAME) as PackedScene).instantiate() as PachinkoGame
	add_child_autofree(game)
	game.rules.start_game()
	game.board_view.aim_preview().preview()  # the flights are measured on a worker thread
	return game


func test_drawing_back_shows_the_flight_at_that_power() -> void:
	var game := _playing_game()
	var aim := game.board_view.aim_preview()
	aim._process(0.5)
	assert_false(aim.is_showing(), "nothing shows while no one aims")
	game.rules.begin_charge()
	game.rules.set_power(42.0)
	aim._process(0.5)
	assert_true(aim.is_showing(), "drawing back shows the flight")
	assert_eq(aim.shown_power(), 42.0)
	assert_eq(aim.preview().path(42.0)[0], LaunchRail.entry_point(game.rules.level))
	game.rules.release()
	aim._process(0.5)
	assert_false(aim.is_showing(), "gone once the ball is away")


func test_turning_the_handle_shows_its_flight_for_a_moment() -> void:
	var game := _playing_game()
	var aim := game.board_view.aim_preview()
	game.rules.handle.set_power(75.0)
	aim._process(0.1)
	assert_true(aim.is_showing(), "a turn of the handle is aiming too")
	assert_eq(aim.shown_power(), 75.0)
	for i in 20:
		aim._process(0.1)
	assert_false(aim.is_showing(), "and it goes once the handle rests")


func test_the_bar_keeps_the_last_shot() -> void:
	var game := _playing_game()
	assert_eq(game.launcher.last_shot(), -1.0, "no mark before the first shot")
	game.rules.begin_charge()
	game.rules.set_power(63.0)
	game.rules.release()
	assert_eq(game.launcher.last_shot(), 63.0, "the bar marks the shot's power")
