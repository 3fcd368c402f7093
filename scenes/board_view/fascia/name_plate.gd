class_name NamePlate
extends RefCounted
## A machine's name plate: the board's name on a plate that sits on the top of the ring band,
## shaped and coloured by the machine (FasciaPalette.PlateStyle): a scrolled cartouche, a
## wooden sign, a leafy pill, a neon tube box or black lacquer with blossoms. Drawn from a
## CanvasItem's `_draw()` in board pixels, once (the game bakes it with the static layers).

## Letter size and the plate's height, in board pixels.
const FONT_SIZE := 17
const HEIGHT := 30.0
## Room left and right of the name, and the narrowest and widest plate.
const PADDING := 30.0
const MIN_WIDTH := 150.0
const MAX_WIDTH := 300.0


## The plate's rectangle for `level` (centred on the ring's top, over the band).
static func rect_of(level: BoardLevel, text_width: float) -> Rect2:
	var width := clampf(text_width + PADDING * 2.0, MIN_WIDTH, MAX_WIDTH)
	var center := level.ring_center + Vector2(0.0, -level.ring_radius - 13.0)
	return Rect2(center - Vector2(width, HEIGHT) * 0.5, Vector2(width, HEIGHT))


## Draws `level`'s name plate in `palette`'s style on `canvas`.
static func draw(canvas: CanvasItem, level: BoardLevel, palette: FasciaPalette) -> void:
	var font := ThemeDB.fallback_font
	var text := level.display_name if not level.display_name.is_empty() else level.board_id
	var text_size := font.get_string_size(text, HORIZONTAL_ALIGNMENT_LEFT, -1, FONT_SIZE)
	var plate := rect_of(level, text_size.x)
	canvas.draw_rect(plate.grow(3.0), Color(0, 0, 0, 0.35))
	match palette.plate_style:
		FasciaPalette.PlateStyle.SIGNBOARD:
			_signboard(canvas, plate, palette)
		FasciaPalette.PlateStyle.LEAF:
			_leaf(canvas, plate, palette)
		FasciaPalette.PlateStyle.NEON_TUBE:
			_neon(canvas, plate, palette)
		FasciaPalette.PlateStyle.LACQUER:
			_lacquer(canvas, plate, palette)
		_:
			_cartouche(canvas, plate, palette)
	var width := plate.size.x - PADDING * 1.4
	var base := Vector2(plate.position.x + PADDING * 0.7, plate.get_center().y + FONT_SIZE * 0.36)
	var outline := 6 if palette.plate_style == FasciaPalette.PlateStyle.NEON_TUBE else 3
	var outline_color := (
		Color(palette.plate_text, 0.35)
		if palette.plate_style == FasciaPalette.PlateStyle.NEON_TUBE
		else Color(0, 0, 0, 0.6)
	)
	canvas.draw_string_outline(
		font, base, text, HORIZONTAL_ALIGNMENT_CENTER, width, FONT_SIZE, outline, outline_color
	)
	canvas.draw_string(
		font, base, text, HORIZONTAL_ALIGNMENT_CENTER, width, FONT_SIZE, palette.plate_text
	)


static func _box(face: Color, border: Color, border_width: int, radius: int) -> StyleBoxFlat:
	var box := StyleBoxFlat.new()
	box.bg_color = face
	box.border_color = border
	box.set_border_width_all(border_width)
	box.set_corner_radius_all(radius)
	box.anti_aliasing = true
	return box


# Classic: a rounded cartouche with trim-metal scrolls at both ends.
static func _cartouche(canvas: CanvasItem, plate: Rect2, palette: FasciaPalette) -> void:
	canvas.draw_style_box(_box(palette.plate_face, palette.trim, 2, 15), plate)
	for side: float in [-1.0, 1.0]:
		var at := plate.get_center() + Vector2(side * (plate.size.x * 0.5 - 12.0), 0.0)
		var start := PI * 0.5 if side < 0.0 else -PI * 0.5
		canvas.draw_arc(at, 6.0, start, start + PI * 1.5, 12, palette.trim, 2.0, true)
		canvas.draw_circle(at, 2.0, palette.trim)


# Country: a plank sign with a grain line and a nail in each corner.
static func _signboard(canvas: CanvasItem, plate: Rect2, palette: FasciaPalette) -> void:
	canvas.draw_style_box(_box(palette.plate_face, palette.plate_face.darkened(0.45), 3, 3), plate)
	var mid := plate.get_center().y
	var grain := palette.plate_face.darkened(0.25)
	canvas.draw_line(
		Vector2(plate.position.x + 4.0, mid), Vector2(plate.end.x - 4.0, mid), grain, 1.5
	)
	for corner: Vector2 in [Vector2(0, 0), Vector2(1, 0), Vector2(0, 1), Vector2(1, 1)]:
		var at := plate.position + Vector2(7.0, 7.0) + (plate.size - Vector2(14.0, 14.0)) * corner
		canvas.draw_circle(at, 2.2, palette.trim.darkened(0.3))


# Garden: a green pill with a leaf and a tulip head at each end.
static func _leaf(canvas: CanvasItem, plate: Rect2, palette: FasciaPalette) -> void:
	canvas.draw_style_box(_box(palette.plate_face, palette.trim, 2, 15), plate)
	for side: float in [-1.0, 1.0]:
		var at := plate.get_center() + Vector2(side * (plate.size.x * 0.5 - 14.0), 0.0)
		var leaf := PackedVector2Array(
			[
				at + Vector2(-side * 8.0, 6.0),
				at + Vector2(0.0, -3.0),
				at + Vector2(side * 8.0, 8.0),
				at + Vector2(0.0, 11.0),
			]
		)
		canvas.draw_colored_polygon(leaf, palette.ring_light)
		canvas.draw_circle(at + Vector2(0.0, -4.0), 5.0, palette.petal)
		canvas.draw_circle(at + Vector2(-2.0, -6.0), 1.8, palette.petal_light)


# Neon: a dark box outlined by a glowing tube.
static func _neon(canvas: CanvasItem, plate: Rect2, palette: FasciaPalette) -> void:
	for glow in 3:
		var spread := 2.0 + glow * 3.0
		var halo := _box(Color.TRANSPARENT, Color(palette.ring_light, 0.22), int(spread), 10)
		halo.draw_center = false
		canvas.draw_style_box(halo, plate.grow(spread * 0.5))
	canvas.draw_style_box(_box(palette.plate_face, palette.trim, 3, 8), plate)
	canvas.draw_style_box(_box(Color.TRANSPARENT, Color(1, 1, 1, 0.7), 1, 7), plate.grow(-1.0))


# Sakura: black lacquer with a gold edge and blossoms at both ends.
static func _lacquer(canvas: CanvasItem, plate: Rect2, palette: FasciaPalette) -> void:
	canvas.draw_style_box(_box(palette.plate_face, palette.trim, 2, 4), plate)
	for side: float in [-1.0, 1.0]:
		var at := plate.get_center() + Vector2(side * (plate.size.x * 0.5 - 14.0), 0.0)
		for petal in 5:
			var angle := TAU * float(petal) / 5.0 - PI * 0.5
			canvas.draw_circle(at + Vector2.from_angle(angle) * 4.5, 4.0, palette.petal_light)
		canvas.draw_circle(at, 2.2, palette.petal)
