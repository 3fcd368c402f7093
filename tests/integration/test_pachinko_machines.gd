extends GutTest
## The game screen wears the board's machine: the art behind the pins, the ring, the name
## plate, the cabinet and the side panel all follow the board's fascia.

const GAME := "res://scenes/pachinko/pachinko_game.tscn"


func after_each() -> void:
	App.request_board("pachinko", "res://levels/pachinko/classic.board")


func _game_on(board: String) -> PachinkoGame:
	App.request_board("pachinko", board)
	var game := (load(GAME) as PackedScene).instantiate() as PachinkoGame
	add_child(game)
	return game


func test_each_board_dresses_the_screen_as_its_machine() -> void:
	var arts := {}
	for board: String in ["classic", "windmills", "tulips", "fever", "hanami"]:
		var game := _game_on("res://levels/pachinko/%s.board" % board)
		var level := (game.get("rules") as PachinkoRules).level
		var palette := FasciaBook.palette_of(level.fascia)
		var view := game.get_node("BoardView") as BoardView
		assert_eq(view.fascia.texture.resource_path, palette.art_path, board + ": its art")
		assert_eq(view.fascia.modulate, palette.art_tint)
		assert_not_null(view.get_node_or_null("Bake/Static/NamePlate"), board + ": a name plate")
		var ring := view.get_node("Bake/Static/RingBorder")
		assert_eq((ring as BoardLayer).palette(), palette, board + ": the ring in its colours")
		var hud := game.get_node("Hud") as Control
		var style := hud.get_theme_stylebox(&"panel") as StyleBoxFlat
		assert_eq(style.border_color, palette.panel_border, board + ": the side panel")
		var title := game.title
		assert_eq(title.label_settings.font_color, palette.title)
		arts[view.fascia.texture.resource_path] = board
		# one game at a time: five screens open at once each start their own worker threads
		remove_child(game)
		game.free()
	assert_eq(arts.size(), 5, "five boards, five pictures")


func test_a_portrait_window_puts_the_panel_under_a_board_as_wide_as_the_window() -> void:
	var window := get_tree().root
	var before := window.size
	window.size = Vector2i(720, 1280)
	var game := _game_on("res://levels/pachinko/hanami.board")
	game.lay_out()
	var view := game.get_viewport_rect().size
	var hud := (game.get_node("Hud") as Control).get_global_rect()  # as drawn (scaled)
	var board_width := (game.get_node("BoardView") as Node2D).scale.x * 700.0
	window.size = before  # the game lays itself out again for the old size
	assert_gt(view.y, view.x * 1.5, "the window is portrait")
	assert_almost_eq(hud.position.y, view.x, 0.5, "the panel starts under the board")
	assert_almost_eq(hud.get_center().x, view.x * 0.5, 0.5, "centred")
	assert_gt(board_width, view.x * 0.85, "the board takes the window's width")
	remove_child(game)
	game.free()
