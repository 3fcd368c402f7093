class_name BoardBackplate
extends "res://scenes/pachinko/board/board_layer.gd"
## Bottom art layer: the lacquered back plate the ring sits on, with corner scrolls in the
## machine's trim metal. Drawn once per board, in its machine's colours (FasciaPalette).


func _draw() -> void:
	if _level == null:
		return
	var c := _level.ring_center
	var r := _level.ring_radius
	var half := r * 1.1
	var plate := Rect2(c - Vector2(half, half), Vector2(half, half) * 2.0)
	draw_rect(plate.grow(10.0), Color(0, 0, 0, 0.45))
	draw_rect(plate, _palette.plate_edge)
	draw_rect(plate.grow(-6.0), _palette.plate)
	draw_rect(plate.grow(-12.0), _palette.trim.darkened(0.35), false, 2.0)
	# Soft glow behind the ring so the playfield lifts off the plate.
	for i in 6:
		var k := float(i) / 6.0
		draw_circle(c, r * (1.14 - k * 0.1), _palette.glow)
	for corner: Vector2 in [Vector2(-1, -1), Vector2(1, -1), Vector2(-1, 1), Vector2(1, 1)]:
		_draw_scroll(c + corner * (half - 30.0), corner)


# A corner ornament in the trim metal: two nested quarter arcs and a dot, facing into the corner.
func _draw_scroll(at: Vector2, corner: Vector2) -> void:
	var start := atan2(corner.y, corner.x) + PI * 0.75
	var gold := _palette.trim
	draw_arc(at, 18.0, start, start + PI * 1.5, 24, gold, 3.0, true)
	draw_arc(at, 9.0, start + PI, start + PI * 2.5, 16, gold.darkened(0.2), 2.0, true)
	draw_circle(at + corner * 14.0, 3.5, gold)
