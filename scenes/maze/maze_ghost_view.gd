extends Node2D
## Draws the ghost of the best run: translucent balls at positions in board pixels, with a
## dashed rim so they read as "not a real ball" without colour. Put it where board
## pixels are its own coordinates (a child of the board drawing, or under a 3D view's 2D
## overlay) and call `show_balls` every frame; `clear` hides it.

## Fill and rim of a ghost ball: the seed's ball colour washed out, with a dashed rim in the
## seed's purple so it reads on the light floor and beside a real ball.
const FILL := Color(0.94, 0.39, 0.29, 0.38)
const RIM := Color(0.38, 0.25, 0.46, 0.75)
const RIM_WIDTH := 1.4
const RIM_DASHES := 8

var _positions := PackedVector2Array()
var _radius := 0.0


## Shows ghost balls at `positions` (board pixels) with `radius`.
func show_balls(positions: PackedVector2Array, radius: float) -> void:
	_positions = positions
	_radius = radius
	queue_redraw()


## Hides the ghost.
func clear() -> void:
	_positions = PackedVector2Array()
	queue_redraw()


func _draw() -> void:
	if _radius <= 0.0:
		return
	var step := TAU / float(RIM_DASHES)
	for p in _positions:
		draw_circle(p, _radius, FILL)
		for i in RIM_DASHES:
			var from := step * float(i)
			draw_arc(p, _radius - RIM_WIDTH * 0.5, from, from + step * 0.6, 4, RIM, RIM_WIDTH, true)
