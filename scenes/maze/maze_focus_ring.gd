class_name MazeFocusRing
extends RefCounted
## The focus ring of the maze screen's buttons: Godot's default one is a faint white line,
## which vanishes on the light win panel and side panel, so a keyboard or gamepad player
## could not see which button Enter would press. This one is a thick ring in the seed's ink
## colour, drawn a little outside the button so it never hides the button's text.

## The ring's width and how far outside the button it is drawn (px).
const WIDTH := 3
const OUTSET := 4.0
const CORNER := 8


## A focus ring for buttons on the maze screen's light panels.
static func style() -> StyleBoxFlat:
	var ring := StyleBoxFlat.new()
	ring.draw_center = false
	ring.border_color = MazePalette.TEXT
	ring.set_border_width_all(WIDTH)
	ring.set_corner_radius_all(CORNER)
	ring.set_expand_margin_all(OUTSET)
	ring.anti_aliasing = true
	return ring


## Gives `control` the ring as its focus style.
static func apply(control: Control) -> void:
	control.add_theme_stylebox_override("focus", style())


## The WCAG contrast ratio of two colours (1 the same, 21 black on white): a focus ring
## wants at least 3 against what lies round it.
static func contrast(a: Color, b: Color) -> float:
	var la := a.get_luminance()
	var lb := b.get_luminance()
	return (maxf(la, lb) + 0.05) / (minf(la, lb) + 0.05)
