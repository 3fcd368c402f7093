extends GutTest
## The balls in a small landscape window (900 × 700, the size a play trial used): the game
## draws the 1280 × 720 design at 0.7 there and its side panel's text grows to stay
## readable, so a ball of The Deep was about 8 px on the screen. The board now gets the
## room its shape wants (the panel as a column beside it or a band under it, whichever
## draws the board bigger), and every shipped board's balls are measured on the screen,
## anywhere on the board at any tilt.

const StretchedWindow := preload("res://tests/integration/stretched_window.gd")
const TestMazeFraming := preload("res://tests/integration/test_maze_framing.gd")
const GAME := preload("res://scenes/maze/maze_game.tscn")
## The smallest a ball may be on the screen of a 900 × 700 window (px across).
const MIN_SMALL_WINDOW_BALL_PX := 10.0


func test_every_board_s_balls_read_in_a_900_by_700_window() -> void:
	var report: Array[String] = []
	for board in TestMazeFraming.shipped_boards():
		var smallest := await _smallest_on_screen(board, Vector2i(900, 700))
		report.append("%s %.1f" % [board, smallest])
		assert_gte(
			smallest,
			MIN_SMALL_WINDOW_BALL_PX,
			"%s at 900x700: a ball is %.1f px on the screen" % [board, smallest]
		)
	gut.p("smallest ball px on screen at 900x700 (any corner, any tilt): " + ", ".join(report))
	App.request_board(BoardLevel.MAZE_NAME, "res://levels/maze/classic.board")


## The smallest a ball of `board` is drawn on the screen of a `size` window (screen px),
## over the board's corners and every tilt the framing test tries.
func _smallest_on_screen(board: String, size: Vector2i) -> float:
	var path := "res://levels/maze/%s.board" % board
	App.request_board(BoardLevel.MAZE_NAME, path)
	var game: MazeGame = await StretchedWindow.open(self, GAME, size, 3)
	var stage := game.stage()
	var level: BoardLevel = game.rules.level
	assert_true(level.board_id.ends_with(board), "the game opened %s" % board)
	var screen := game.get_viewport().get_final_transform().get_scale().y
	var smallest := INF
	for tilt in TestMazeFraming.TILTS:
		stage.set_tilt(tilt)
		smallest = minf(smallest, TestMazeFraming.smallest_ball_px(stage, level) * screen)
	stage.set_tilt(Vector2.ZERO)
	game.get_parent().queue_free()
	await wait_process_frames(1)
	return smallest
