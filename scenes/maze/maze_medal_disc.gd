class_name MazeMedalDisc
extends Control
## The medal a win earned, drawn large on the win card: a disc in the medal's colour hung on
## a ribbon, its name across it. Hidden when the run earned none.

## The disc's radius and the ribbon's length above it, in the card's units.
const RADIUS := 54.0
const RIBBON := 34.0
const RIBBON_COLOUR := Color(0.16, 0.3, 0.62)
const FONT_SIZE := 22

## The medal shown (Medals.Medal).
var medal: int = Medals.Medal.NONE:
	set(value):
		medal = value
		visible = medal != Medals.Medal.NONE
		queue_redraw()


func _init() -> void:
	custom_minimum_size = Vector2(RADIUS * 2.0 + 8.0, RADIUS * 2.0 + RIBBON + 6.0)
	mouse_filter = Control.MOUSE_FILTER_IGNORE
	visible = false


func _draw() -> void:
	if medal == Medals.Medal.NONE:
		return
	var colour: Color = MedalBadges.COLORS.get(medal, Color.GRAY)
	var centre := Vector2(size.x * 0.5, RIBBON + RADIUS)
	var top := centre.x
	# the ribbon: two bands meeting behind the disc
	for side: float in [-1.0, 1.0]:
		var band := PackedVector2Array(
			[
				Vector2(top + side * 30.0, 0.0),
				Vector2(top + side * 12.0, 0.0),
				Vector2(top - side * 26.0, RIBBON + 12.0),
				Vector2(top - side * 8.0, RIBBON + 12.0),
			]
		)
		draw_colored_polygon(band, RIBBON_COLOUR.lightened(0.12 if side < 0.0 else 0.0))
	draw_circle(centre, RADIUS, colour.darkened(0.35))
	draw_circle(centre, RADIUS - 5.0, colour)
	draw_circle(centre + Vector2(-RADIUS * 0.3, -RADIUS * 0.3), RADIUS * 0.28, Color(1, 1, 1, 0.25))
	var font := get_theme_default_font()
	var text := Medals.name_of(medal as Medals.Medal).to_upper()
	var width := font.get_string_size(text, HORIZONTAL_ALIGNMENT_LEFT, -1, FONT_SIZE).x
	var baseline := centre + Vector2(-width * 0.5, FONT_SIZE * 0.35)
	draw_string(
		font, baseline, text, HORIZONTAL_ALIGNMENT_LEFT, -1, FONT_SIZE, colour.darkened(0.7)
	)
