extends GutTest
## A maze card's picture is the board as it opens: in easy mode, without hard mode's black
## holes (trial 6 read the holes on the cards as part of the easy game). Pachinko pictures
## keep every layer.


func test_a_maze_picture_leaves_out_the_holes() -> void:
	var level := BoardLoader.load_board("res://levels/maze/crossroads.board").level
	assert_false(level.holes.is_empty(), "a board with hard-mode holes")
	var layers := BoardThumbnail.layers_for(level)
	assert_eq(layers & BoardPainter.Layer.HOLES, 0, "no holes on its card")
	assert_ne(layers & BoardPainter.Layer.WALLS, 0, "its walls drawn")
	assert_ne(layers & BoardPainter.Layer.GOAL, 0, "its goal drawn")


func test_a_pachinko_picture_keeps_every_layer() -> void:
	var level := BoardLoader.load_board("res://levels/pachinko/classic.board").level
	assert_eq(BoardThumbnail.layers_for(level), BoardPainter.Layer.ALL)
