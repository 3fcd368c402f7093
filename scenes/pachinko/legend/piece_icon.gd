class_name PieceIcon
extends Control
## A small drawing of one kind of board piece, as it looks on the board: a plain pocket's
## cup, a bonus pocket drawn by BonusPainter (a tulip with its petals open, so a player
## sees what a catch does), or the board's first windmill drawn by WindmillPainter. A pocket
## takes its colours from the board's machine (FasciaBook), as the pockets on the board do:
## Windmills' card showed a red pocket beside the board's blue ones.

## Room for the drawing, px.
const SIZE := Vector2(64.0, 50.0)

var _level: BoardLevel
var _piece := BoardPieces.Piece.POCKET


func _init(level: BoardLevel, piece: BoardPieces.Piece) -> void:
	_level = level
	_piece = piece
	custom_minimum_size = SIZE
	mouse_filter = Control.MOUSE_FILTER_IGNORE


## The colour of the pocket's petals in the drawing: the board's machine's (its pockets').
func pocket_colour() -> Color:
	return FasciaBook.palette_of(_level.fascia).petal


func _draw() -> void:
	if _piece == BoardPieces.Piece.POCKET:
		_draw_pocket()
		return
	if _piece == BoardPieces.Piece.WINDMILL:
		_draw_windmill()
		return
	var specs := BoardPieces.bonus_specs(_level, _piece)
	if specs.is_empty():
		return
	var spec := specs[0].duplicate() as BonusPocketSpec
	spec.position = Vector2.ZERO
	# Scaled to fit: the widest piece (an attacker, 60-70 px) fills the box.
	var zoom := minf(1.0, (SIZE.x - 8.0) / (spec.width + 16.0))
	draw_set_transform(Vector2(SIZE.x * 0.5, 14.0), 0.0, Vector2(zoom, zoom))
	BonusPainter.draw_pocket(self, _level, spec, _piece == BoardPieces.Piece.TULIP, 0.0)
	draw_set_transform(Vector2.ZERO)


# The board's first wheel at rest, scaled to fill the box's height.
func _draw_windmill() -> void:
	if _level.windmills.is_empty() or _level.windmills[0] == null:
		return
	var spec := _level.windmills[0].duplicate() as WindmillSpec
	spec.position = Vector2.ZERO
	var zoom := (SIZE.y * 0.5 - 3.0) / maxf(spec.sweep_radius(), 1.0)
	draw_set_transform(SIZE * 0.5, 0.0, Vector2(zoom, zoom))
	WindmillPainter.draw_wheel(self, spec, -PI * 0.5)
	draw_set_transform(Vector2.ZERO)


func _draw_pocket() -> void:
	var half := 11.0
	var top := Vector2(SIZE.x * 0.5, 16.0)
	var bottom := top + Vector2(0.0, 12.0)
	var rim := PackedVector2Array([top + Vector2(-half, 0.0)])
	for s in 15:
		var a := PI - PI * float(s) / 14.0
		rim.append(bottom + Vector2(cos(a), sin(a)) * half)
	rim.append(top + Vector2(half, 0.0))
	var palette := FasciaBook.palette_of(_level.fascia)
	var petal := pocket_colour()
	draw_polyline(rim, petal.darkened(0.4), 8.0, true)
	draw_polyline(rim, petal, 5.0, true)
	draw_polyline(rim, palette.petal_light, 1.5, true)
	for side: float in [-1.0, 1.0]:
		var root := top + Vector2(side * half, 0.0)
		var leaf := PackedVector2Array(
			[root, root + Vector2(side * 10.0, -6.0), root + Vector2(side * 4.0, -11.0), root]
		)
		draw_colored_polygon(leaf, petal)
		draw_polyline(leaf, palette.pocket_trim, 1.5, true)
	draw_circle(bottom + Vector2(0.0, half - 3.0), 2.5, palette.pocket_trim)
