class_name ReadableText
extends RefCounted
## The one rule for text a player must be able to read on any screen. The project draws its
## 1280 × 720 design stretched to the window (canvas_items), so a portrait phone draws it at
## 0.56 and a small window smaller than designed; a screen then draws its text bigger by
## growth_at(), until its smallest words are MIN_SCREEN_PX tall on the screen. How it grows
## (fonts, or the whole panel scaled) is each screen's own.

## The smallest text a player is shown, in screen pixels.
const MIN_SCREEN_PX := 14.0


## How many times bigger text of `font_size` (design units) must be drawn, in a view drawn
## `screen_scale` screen pixels per unit, to read at MIN_SCREEN_PX; 1 when it already does.
static func growth_at(font_size: float, screen_scale: float) -> float:
	return maxf(1.0, MIN_SCREEN_PX / (font_size * maxf(screen_scale, 0.01)))


## Screen pixels per view unit in `node`'s viewport (the window's stretch).
static func screen_scale_of(node: Node) -> float:
	return node.get_viewport().get_final_transform().get_scale().y
