extends GutTest
## Balls a player can see (issue 41): on every pachinko machine at 1280 × 720 the steel of
## a ball is at least 10 px across on the screen, with a highlight and a contact shadow, and
## a pin or a pocket that is hit flashes for long enough and brightly enough to be seen.

const GAME := preload("res://scenes/pachinko/pachinko_game.tscn")
const StretchedWindow := preload("res://tests/integration/stretched_window.gd")
const BOARDS_DIR := "res://levels/pachinko"
## The smallest ball a player picks out of a busy fascia, screen pixels across.
const MIN_BALL_PX := 10.0
## Steel darker than this reads as the rim or the art, not as the ball.
const STEEL_LUMINANCE := 0.3


func after_each() -> void:
	App.request_board("pachinko", "res://levels/pachinko/classic.board")


func _boards() -> PackedStringArray:
	var found := PackedStringArray()
	for file in DirAccess.get_files_at(BOARDS_DIR):
		if file.get_extension() == "board":
			found.append("%s/%s" % [BOARDS_DIR, file])
	return found


# The share of the ball texture's width, across its middle, that reads as steel: opaque and
# lighter than the rim.
func _steel_share() -> float:
	var size := 64
	var image := BallLayer.make_ball_image(size)
	var steel := 0
	for x in size:
		var pixel := image.get_pixel(x, 32)
		if pixel.a >= 0.5 and pixel.get_luminance() >= STEEL_LUMINANCE:
			steel += 1
	return float(steel) / float(size)


func test_every_machine_draws_its_balls_at_least_10_px_across_at_1280x720() -> void:
	var boards := _boards()
	assert_gte(boards.size(), 5, "the shipped machines")
	var share := _steel_share()
	for board in boards:
		App.request_board("pachinko", board)
		var game := await StretchedWindow.open(self, GAME, Vector2i(1280, 720), 2) as PachinkoGame
		var view := game.get_node("BoardView") as BoardView
		var on_screen := (
			view.get_global_transform_with_canvas().get_scale().x
			* game.get_viewport().get_final_transform().get_scale().x
		)
		var across := view.balls.drawn_radius() * 2.0 * on_screen * share
		assert_gte(across, MIN_BALL_PX, "%s: a ball's steel is %.1f px across" % [board, across])
		# the game leaves its window first: a window going away resizes on its way out
		var window := game.get_parent()
		window.remove_child(game)
		game.free()
		window.queue_free()


func test_a_ball_has_a_bright_highlight_upper_left_and_a_dark_shadow_lower_right() -> void:
	var size := 64
	var ball := BallLayer.make_ball_image(size)
	var brightest := 0.0
	for y in 32:
		for x in 32:
			brightest = maxf(brightest, ball.get_pixel(x, y).get_luminance())
	# the quarter of the ball between its centre and its lower right edge
	var lower_right := 0.0
	for y in range(32, 48):
		for x in range(32, 48):
			lower_right += ball.get_pixel(x, y).get_luminance()
	lower_right /= 256.0
	assert_gt(brightest, 0.9, "a highlight near white")
	assert_gt(brightest - lower_right, 0.2, "that stands out from the steel away from the light")
	var shadowed := BallLayer.make_shadowed_ball_texture(size).get_image()
	shadowed.decompress()
	var span := shadowed.get_width()
	var centre := Vector2(span, span) * 0.5
	# just outside the ball's edge, down and to the right: the shadow on the fascia
	var beside := centre + Vector2(0.45, 0.45).normalized() * (size * 0.5 + 2.0)
	var shade := shadowed.get_pixelv(Vector2i(beside))
	assert_gt(shade.a, 0.5, "a contact shadow dark enough to read on light art")
	assert_lt(shade.get_luminance(), 0.1, "and dark")


func test_a_hit_pin_flashes_bright_for_half_a_second() -> void:
	var lights := PinLights.new()
	add_child_autofree(lights)
	lights.bind(PachinkoRules.new(BoardLoader.load_board(BOARDS_DIR + "/classic.board").level))
	lights.light(0, PinLights.GLOW, 1.0)
	assert_gte(lights.flash_reach() * 2.0, 18.0, "the flash reaches about 20 board px across")
	for frame in 30:
		lights._process(1.0 / 60.0)
	assert_gt(lights.glow_of(0), 0.1, "still lit half a second later")


func test_a_pocket_that_pays_flashes_white_hot() -> void:
	var level := BoardLoader.load_board(BOARDS_DIR + "/classic.board").level
	var pockets := PocketArt.new()
	add_child_autofree(pockets)
	pockets.setup(level)
	pockets.celebrate(0)
	var palette := FasciaBook.palette_of(level.fascia)
	var hot := PocketArt.flash_color(palette.petal, pockets.glow_of(0))
	assert_gt(hot.get_luminance(), 0.8, "the cup goes white-hot")
	for frame in 30:
		pockets._process(1.0 / 60.0)
	assert_gt(pockets.glow_of(0), 0.3, "and is still glowing half a second later")
