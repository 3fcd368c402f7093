class_name BoardLayer
extends Node2D
## One drawn layer of the pachinko board. BoardView hands every layer the board through
## `setup()`; a layer keeps it, and the look of the machine it is dressed as (`_palette`,
## FasciaBook), and redraws. Layers that hold more state extend `setup()`.

var _level: BoardLevel
var _palette: FasciaPalette = FasciaBook.palette_of(FasciaNames.CLASSIC)


## The machine's colours this layer is drawn in.
func palette() -> FasciaPalette:
	return _palette


## Shows `level` on this layer.
func setup(level: BoardLevel) -> void:
	_level = level
	_palette = FasciaBook.palette_of(level.fascia)
	queue_redraw()
