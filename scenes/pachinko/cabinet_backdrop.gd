class_name CabinetBackdrop
extends TextureRect
## The cabinet behind everything: a deep gradient in the machine's colours with faint
## diagonal light, so the board and the HUD sit on something that looks like a machine, not
## an empty window. Painted once per machine into a small texture and stretched (one quad a
## frame, cheap even without a GPU).

const PAINT_SIZE := Vector2i(320, 180)

# Painted once per machine and run: a restart or a second game reuses it.
static var _painted: Dictionary[String, ImageTexture] = {}


func _ready() -> void:
	mouse_filter = Control.MOUSE_FILTER_IGNORE
	expand_mode = TextureRect.EXPAND_IGNORE_SIZE
	stretch_mode = TextureRect.STRETCH_SCALE
	if texture == null:
		dress(FasciaBook.palette_of(FasciaNames.CLASSIC))


## Paints the cabinet in `palette`'s backdrop colours.
func dress(palette: FasciaPalette) -> void:
	if not _painted.has(palette.name):
		var image := paint(PAINT_SIZE, palette.backdrop_top, palette.backdrop_bottom)
		_painted[palette.name] = ImageTexture.create_from_image(image)
	texture = _painted[palette.name]


## The backdrop picture at `pixels` (width, height), from `top` down to `bottom`.
static func paint(pixels: Vector2i, top: Color, bottom: Color) -> Image:
	var image := Image.create_empty(pixels.x, pixels.y, false, Image.FORMAT_RGB8)
	for y in pixels.y:
		var t := float(y) / float(pixels.y - 1)
		var base := top.lerp(bottom, t)
		for x in pixels.x:
			# Six soft diagonal bands of light, leaning left as they go down.
			var u := (float(x) + float(y) * 1.1) / float(pixels.x) * 6.0
			var band := maxf(0.0, 1.0 - absf(fposmod(u, 1.0) - 0.5) * 8.0) * 0.025
			image.set_pixel(x, y, base.lightened(band))
	return image
