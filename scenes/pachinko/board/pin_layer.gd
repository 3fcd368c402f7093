extends "res://scenes/pachinko/board/board_layer.gd"
## Every pin of the board in one static draw: brass nail heads with a shadow and a glint.
## Special (catching) pins are drawn as gold diamonds, so they differ by shape, not only by
## colour. Redrawn only when the board changes.

const HEAD := Color("ecd9a0")
const HEAD_DARK := Color("6f5a2c")
const GLINT := Color("fff6d8")
const SPECIAL := Color("ffd23f")


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
			draw_special(self, p, r)
			continue
		draw_circle(p + shadow, r, Color(0, 0, 0, 0.55))
		draw_circle(p, r + 0.6, Color(0.05, 0.03, 0.08, 0.8))
		draw_circle(p, r, HEAD_DARK)
		draw_circle(p - Vector2(r, r) * 0.15, r * 0.75, HEAD)
		draw_circle(p - Vector2(r, r) * 0.35, r * 0.3, GLINT)


## A special pin: a gold diamond with a dark outline (also used by the pocket art).
static func draw_special(canvas: CanvasItem, at: Vector2, pin_radius: float) -> void:
	var s := pin_radius * 1.9
	var diamond := PackedVector2Array(
		[at + Vector2(0, -s), at + Vector2(s, 0), at + Vector2(0, s), at + Vector2(-s, 0)]
	)
	canvas.draw_colored_polygon(diamond, SPECIAL)
	diamond.append(diamond[0])
	canvas.draw_polyline(diamond, Color("5a3c00"), 1.5, true)
	canvas.draw_circle(at - Vector2(s, s) * 0.2, s * 0.22, GLINT)
