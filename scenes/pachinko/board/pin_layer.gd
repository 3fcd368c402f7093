class_name PinLayer
extends "res://scenes/pachinko/board/board_layer.gd"
## Every pin of the board in one static draw: nail heads in the machine's pin colours with a
## shadow and a glint, special (catching) pins as PinArt's gold diamonds. Redrawn only when
## the board changes.


func _draw() -> void:
	if _level == null:
		return
	# Pins are drawn a little larger than their physical radius: a 1.5 px nail head would
	# vanish on the art. The ball still touches where the physics says.
	var r := maxf(_level.pin_radius + 0.8, 2.2)
	var shadow := Vector2(r * 0.45, r * 0.6)
	for i in _level.pins.size():
		var p := _level.pins[i]
		if i < _level.pin_special.size() and _level.pin_special[i] != 0:
			PinArt.draw_special(self, p, r)
			continue
		draw_circle(p + shadow, r, Color(0, 0, 0, 0.55))
		draw_circle(p, r + 0.6, Color(0.05, 0.03, 0.08, 0.8))
		draw_circle(p, r, _palette.pin_dark)
		draw_circle(p - Vector2(r, r) * 0.15, r * 0.75, _palette.pin_head)
		draw_circle(p - Vector2(r, r) * 0.35, r * 0.3, _palette.pin_glint)
