class_name BoardThumbnail
extends Control
## A board drawn small, fitted into this control's rect, for the level select. The drawing
## is the shared BoardPainter's (the same as the editor's and the games'), which marks
## special pins, holes and the goal by shape as well as colour. No board draws a cross.
## A maze's picture leaves out its black holes: a board opens in easy mode, which has none
## (trial 6 read the holes on the cards as part of the easy game).

const BACK_COLOR := Color(0.06, 0.07, 0.11)
const FRAME_COLOR := Color(0.33, 0.4, 0.57)
const BROKEN_COLOR := Color(0.75, 0.38, 0.34)
const MARGIN := 6.0

## The board to draw; null draws the "broken board" cross (unless `waiting`).
var level: BoardLevel = null:
	set(value):
		level = value
		waiting = false
		queue_redraw()
## True while the board is still loading: an empty frame, no cross.
var waiting := false:
	set(value):
		waiting = value
		queue_redraw()


func _draw() -> void:
	var rect := Rect2(Vector2.ZERO, size)
	draw_rect(rect, BACK_COLOR)
	if level == null and waiting:
		pass
	elif level == null:
		var centre := size * 0.5
		var arm := minf(size.x, size.y) * 0.18
		draw_line(centre - Vector2(arm, arm), centre + Vector2(arm, arm), BROKEN_COLOR, 6.0)
		draw_line(centre - Vector2(arm, -arm), centre + Vector2(arm, -arm), BROKEN_COLOR, 6.0)
	else:
		BoardPainter.draw_thumbnail(self, level, rect.grow(-MARGIN), layers_for(level))
	draw_rect(rect, FRAME_COLOR, false, 2.0)


## The painter's layers a thumbnail of `board` draws: all but a maze's holes (hard mode's).
static func layers_for(board: BoardLevel) -> int:
	if board != null and board.is_maze():
		return BoardPainter.Layer.ALL & ~BoardPainter.Layer.HOLES
	return BoardPainter.Layer.ALL
