class_name FasciaPalette
extends RefCounted
## One machine's look (FasciaNames): the art behind the pins, the colours of the plate, ring,
## pins and pockets, of the cabinet behind the board and of the side panel, and how its name
## plate is shaped. FasciaBook holds the five; every picture of a pachinko board reads them.

## The name plate's shape (NamePlate draws each).
enum PlateStyle { CARTOUCHE, SIGNBOARD, LEAF, NEON_TUBE, LACQUER }

## The machine's name (FasciaNames.NAMES).
var name := FasciaNames.CLASSIC
## The disc of art inside the ring (an SVG of our own, 1000 px square, clipped to a circle).
var art_path := ""
## Multiplied into the art so the pins stay the brightest thing on it.
var art_tint := Color.WHITE
## The cabinet behind everything: top and bottom of its gradient.
var backdrop_top := Color.BLACK
var backdrop_bottom := Color.BLACK
## The back plate the ring sits on, its edge, and the metal of its ornaments and name plate.
var plate := Color.BLACK
var plate_edge := Color.BLACK
var trim := Color.WHITE
## The soft glow behind the ring.
var glow := Color.TRANSPARENT
## The ring band, its highlight and the lip the balls touch.
var ring := Color.BLACK
var ring_light := Color.WHITE
var ring_lip := Color.WHITE
## Pin heads: body, shade and glint.
var pin_head := Color.WHITE
var pin_dark := Color.GRAY
var pin_glint := Color.WHITE
## The pockets' petals, their highlight and their trim (leaf, outline, payout text).
var petal := Color.RED
var petal_light := Color.PINK
var pocket_trim := Color.GOLD
## The side panel: background, its border, the stats box and its border, the title and the
## notes under the stats.
var panel := Color.BLACK
var panel_border := Color.WHITE
var box := Color.BLACK
var box_border := Color.WHITE
var title := Color.WHITE
var title_outline := Color.BLACK
var notes := Color.GRAY
## The name plate: its shape, face colour and lettering.
var plate_style := PlateStyle.CARTOUCHE
var plate_face := Color.BLACK
var plate_text := Color.WHITE


## A palette named `fascia_name` with the given fields (property name -> value).
static func made(fascia_name: String, fields: Dictionary) -> FasciaPalette:
	var palette := FasciaPalette.new()
	palette.name = fascia_name
	for key: String in fields:
		if not key in palette:
			push_error("FasciaPalette: no field '%s' (%s)" % [key, fascia_name])
			continue
		palette.set(key, fields[key])
	return palette
