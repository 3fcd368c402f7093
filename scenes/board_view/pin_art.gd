class_name PinArt
extends RefCounted
## How a pin looks, shared by every picture of a board (the game's pin layer, the pocket and
## bonus art, the menus' and editor's painter): brass nail heads, and special (catching) pins
## as gold diamonds, so they differ by shape, not only by colour.

const HEAD := Color("ecd9a0")
const HEAD_DARK := Color("6f5a2c")
const GLINT := Color("fff6d8")
const SPECIAL := Color("ffd23f")


## A special pin: a gold diamond with a dark outline.
static func draw_special(canvas: CanvasItem, at: Vector2, pin_radius: float) -> void:
	var s := pin_radius * 1.9
	var diamond := PackedVector2Array(
		[at + Vector2(0, -s), at + Vector2(s, 0), at + Vector2(0, s), at + Vector2(-s, 0)]
	)
	canvas.draw_colored_polygon(diamond, SPECIAL)
	diamond.append(diamond[0])
	canvas.draw_polyline(diamond, Color("5a3c00"), 1.5, true)
	canvas.draw_circle(at - Vector2(s, s) * 0.2, s * 0.22, GLINT)
