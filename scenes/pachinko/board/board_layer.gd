extends Node2D
## One drawn layer of the pachinko board. BoardView hands every layer the board through
## `setup()`; a layer keeps it and redraws. Layers that hold more state extend `setup()`.

var _level: BoardLevel


## Shows `level` on this layer.
func setup(level: BoardLevel) -> void:
	_level = level
	queue_redraw()
