class_name NamePlateLayer
extends "res://scenes/pachinko/board/board_layer.gd"
## The machine's name plate over the top of the ring band (NamePlate), baked with the other
## static layers.


func _draw() -> void:
	if _level != null:
		NamePlate.draw(self, _level, _palette)
