extends Control
## The cabinet behind everything: a deep gradient with faint diagonal light, so the board
## and the HUD sit on something that looks like a machine, not an empty window.

const TOP := Color("211436")
const BOTTOM := Color("07050d")


func _ready() -> void:
	mouse_filter = Control.MOUSE_FILTER_IGNORE
	resized.connect(queue_redraw)


func _draw() -> void:
	var bands := 24
	for i in bands:
		var t := float(i) / float(bands)
		var rect := Rect2(0.0, size.y * t, size.x, size.y / bands + 1.0)
		draw_rect(rect, TOP.lerp(BOTTOM, t))
	for i in 6:
		var x := size.x * (0.1 + 0.17 * i)
		var band := PackedVector2Array(
			[Vector2(x, 0), Vector2(x + 60, 0), Vector2(x - 260, size.y), Vector2(x - 320, size.y)]
		)
		draw_colored_polygon(band, Color(1, 1, 1, 0.018))
