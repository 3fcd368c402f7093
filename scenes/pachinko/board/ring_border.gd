class_name RingBorder
extends "res://scenes/pachinko/board/board_layer.gd"
## The ring border: an enamel band in the machine's ring colour (FasciaPalette) with a
## bright lip, the edge balls never pass.

## Band width in pixels.
@export var band := 22.0


func _draw() -> void:
	if _level == null:
		return
	var c := _level.ring_center
	var r := _level.ring_radius
	var segments := 160
	var enamel := _palette.ring
	var enamel_light := _palette.ring_light
	draw_arc(c, r + band * 0.5 + 2.0, 0.0, TAU, segments, enamel.darkened(0.45), band + 4.0, true)
	draw_arc(c, r + band * 0.5, 0.0, TAU, segments, enamel, band, true)
	# A lighter stripe offset up-left reads as light falling on a rounded band.
	draw_arc(c, r + band * 0.42, PI * 0.9, PI * 1.9, 80, enamel_light, band * 0.3, true)
	# Chrome lip where the ball touches, and a thin dark line inside it.
	draw_arc(c, r + 1.5, 0.0, TAU, segments, _palette.ring_lip, 3.0, true)
	draw_arc(c, r - 0.5, 0.0, TAU, segments, Color(0, 0, 0, 0.35), 1.0, true)
	# Rivets around the band.
	for i in 24:
		var a := TAU * float(i) / 24.0
		var p := c + Vector2(cos(a), sin(a)) * (r + band * 0.55)
		draw_circle(p, 2.6, enamel.darkened(0.5))
		draw_circle(p - Vector2(0.6, 0.6), 1.6, enamel_light.lightened(0.3))
