extends GutTest
## The flipper's drag follows the board's size on the screen. The rules count one point of
## power per pixel dragged up, in the view's units: on a portrait phone the board is drawn
## 1.8 times bigger in those units (0.56 of them to a screen pixel), so full power took a
## drag of 56 screen pixels beside a board 700 screen pixels across, where 1280 × 720 asks
## 100. Now a full-power drag is the same share of the board in every window.

const GAME := preload("res://scenes/pachinko/pachinko_game.tscn")
const StretchedWindow := preload("res://tests/integration/stretched_window.gd")
const SIZES: Array[Vector2i] = [Vector2i(1280, 720), Vector2i(900, 700), Vector2i(720, 1280)]


func before_each() -> void:
	App.request_board("pachinko", "res://levels/pachinko/classic.board")


func _game_in_window(size: Vector2i) -> PachinkoGame:
	return await StretchedWindow.open(self, GAME, size, 4) as PachinkoGame


# Presses the grip at `at`, drags it `up` view units and returns the power drawn.
func _drag(game: PachinkoGame, at: Vector2, up: float) -> float:
	game.launcher.flipper_pressed.emit(at)
	var motion := InputEventMouseMotion.new()
	motion.position = at - Vector2(0.0, up)
	game._input(motion)
	var power := game.rules.power
	game.rules.cancel_draw()
	return power


func test_a_full_power_drag_is_the_same_share_of_the_board_everywhere() -> void:
	var shares := []
	for size in SIZES:
		var game := await _game_in_window(size)
		game.rules.start_game()
		var full := game.full_power_drag()
		var at := game.launcher.get_global_rect().get_center()
		assert_almost_eq(_drag(game, at, full), 100.0, 0.01, "%s: the full drag" % size)
		assert_almost_eq(_drag(game, at, full * 0.5), 50.0, 0.01, "%s: half of it" % size)
		shares.append(full / game.board_view.scale.x)
		game.free()  # before its window
	for i in shares.size():
		assert_almost_eq(
			shares[i], shares[0], 0.01, "%s: board pixels dragged for full power" % SIZES[i]
		)


func test_a_phone_asks_a_drag_as_long_on_the_screen_as_the_design() -> void:
	var game := await _game_in_window(Vector2i(720, 1280))
	game.rules.start_game()
	var stretch := game.get_viewport().get_final_transform().get_scale().y
	var on_screen := game.full_power_drag() * stretch
	assert_almost_eq(on_screen, 100.0, 10.0, "a full drag is %.0f screen px" % on_screen)
	var at := game.launcher.get_global_rect().get_center()
	assert_lt(_drag(game, at, 100.0), 70.0, "100 view units (56 screen px) is not full power")
	game.free()
