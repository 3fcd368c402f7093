class_name FasciaBook
extends RefCounted
## The five machines' looks (FasciaPalette), by the name a board file gives (FasciaNames).
## Classic keeps the chapter's machine: the moon face and the water dragon on purple enamel.

const ART_FOLDER := "res://assets/pachinko/"
static var _made: Dictionary[String, FasciaPalette] = {}
static var _art: Dictionary[String, Texture2D] = {}


## The look of machine `fascia_name`; an unknown name (the validator refuses one) gets Classic.
static func palette_of(fascia_name: String) -> FasciaPalette:
	var key := fascia_name if FasciaNames.is_known(fascia_name) else FasciaNames.CLASSIC
	if not _made.has(key):
		_made[key] = FasciaPalette.made(key, _fields(key))
	return _made[key]


## The art texture of `palette`, loaded once and kept: a picture drawn from `_draw()` only
## holds the texture's RID, so a texture nobody references would be freed under it (a menu's
## thumbnail showed a grey square).
static func art_of(palette: FasciaPalette) -> Texture2D:
	if not _art.has(palette.art_path):
		_art[palette.art_path] = load(palette.art_path) as Texture2D
	return _art[palette.art_path]


static func _fields(fascia_name: String) -> Dictionary:
	match fascia_name:
		"country":
			return _country()
		"garden":
			return _garden()
		"neon":
			return _neon()
		"sakura":
			return _sakura()
	return _classic()


static func _classic() -> Dictionary:
	return {
		"art_path": ART_FOLDER + "fascia.svg",
		"art_tint": Color(0.78, 0.8, 0.86),
		"backdrop_top": Color("211436"),
		"backdrop_bottom": Color("07050d"),
		"plate": Color("1a1030"),
		"plate_edge": Color("2d1d4f"),
		"trim": Color("c9a04a"),
		"glow": Color(0.35, 0.2, 0.6, 0.05),
		"ring": Color("5b2a86"),
		"ring_light": Color("8e55c4"),
		"ring_lip": Color("e4e7f0"),
		"pin_head": Color("ecd9a0"),
		"pin_dark": Color("6f5a2c"),
		"pin_glint": Color("fff6d8"),
		"petal": Color("c0283c"),
		"petal_light": Color("ee5a5f"),
		"pocket_trim": Color("f2c14e"),
		"panel": Color(0.07, 0.045, 0.13, 0.92),
		"panel_border": Color(0.79, 0.63, 0.29, 0.8),
		"box": Color(0.12, 0.08, 0.22),
		"box_border": Color(0.45, 0.35, 0.65),
		"title": Color(1, 0.86, 0.5),
		"title_outline": Color(0.23, 0.05, 0.1),
		"notes": Color(0.66, 0.62, 0.8),
		"plate_style": FasciaPalette.PlateStyle.CARTOUCHE,
		"plate_face": Color("3b1a5c"),
		"plate_text": Color("ffe3a0"),
	}


# Windmill country: a sunny landscape of fields, a red barn, a silo and hay bales (no mill in
# the picture: the board's real windmills turn in front of it), barn-red ring, walnut plate.
static func _country() -> Dictionary:
	return {
		"art_path": ART_FOLDER + "fascia_country.svg",
		"art_tint": Color(0.74, 0.76, 0.74),
		"backdrop_top": Color("24311c"),
		"backdrop_bottom": Color("080b05"),
		"plate": Color("2a2116"),
		"plate_edge": Color("4a3a24"),
		"trim": Color("d8b26a"),
		"glow": Color(0.95, 0.75, 0.35, 0.05),
		"ring": Color("8c3a22"),
		"ring_light": Color("cf6a3e"),
		"ring_lip": Color("f1eadc"),
		"pin_head": Color("f0e2b0"),
		"pin_dark": Color("5e4a22"),
		"pin_glint": Color("fffbe8"),
		"petal": Color("2f6fb5"),
		"petal_light": Color("7fb6ea"),
		"pocket_trim": Color("f6e3a1"),
		"panel": Color(0.09, 0.075, 0.045, 0.93),
		"panel_border": Color(0.85, 0.7, 0.42, 0.85),
		"box": Color(0.15, 0.12, 0.07),
		"box_border": Color(0.5, 0.4, 0.22),
		"title": Color("ffe6a6"),
		"title_outline": Color("3a2410"),
		"notes": Color("c9bb94"),
		"plate_style": FasciaPalette.PlateStyle.SIGNBOARD,
		"plate_face": Color("7a5230"),
		"plate_text": Color("fff3d6"),
	}


# Tulip garden: beds of tulips in rows under a spring sky, leaf-green ring, pink petals.
static func _garden() -> Dictionary:
	return {
		"art_path": ART_FOLDER + "fascia_garden.svg",
		"art_tint": Color(0.78, 0.8, 0.78),
		"backdrop_top": Color("17331f"),
		"backdrop_bottom": Color("05110a"),
		"plate": Color("11251a"),
		"plate_edge": Color("1f3f2a"),
		"trim": Color("f0cf6a"),
		"glow": Color(0.5, 0.95, 0.55, 0.05),
		"ring": Color("2c7a45"),
		"ring_light": Color("74c785"),
		"ring_lip": Color("eef6e8"),
		"pin_head": Color("f3e6b4"),
		"pin_dark": Color("5c5226"),
		"pin_glint": Color("fffbe6"),
		"petal": Color("d8336f"),
		"petal_light": Color("ff8db5"),
		"pocket_trim": Color("ffd96a"),
		"panel": Color(0.045, 0.1, 0.065, 0.93),
		"panel_border": Color(0.94, 0.6, 0.75, 0.85),
		"box": Color(0.07, 0.17, 0.11),
		"box_border": Color(0.28, 0.58, 0.38),
		"title": Color("ffd0e1"),
		"title_outline": Color("4a0f2c"),
		"notes": Color("a9d3b4"),
		"plate_style": FasciaPalette.PlateStyle.LEAF,
		"plate_face": Color("2c7a45"),
		"plate_text": Color("fff2f6"),
	}


# Fever: a neon night of light tubes and a glowing grid, magenta ring, cyan cups.
static func _neon() -> Dictionary:
	return {
		"art_path": ART_FOLDER + "fascia_neon.svg",
		"art_tint": Color(0.82, 0.8, 0.86),
		"backdrop_top": Color("1d0736"),
		"backdrop_bottom": Color("030108"),
		"plate": Color("0c0618"),
		"plate_edge": Color("2a0c44"),
		"trim": Color("27e3ff"),
		"glow": Color(1.0, 0.2, 0.8, 0.06),
		"ring": Color("b0127f"),
		"ring_light": Color("ff5fd2"),
		"ring_lip": Color("c4f8ff"),
		"pin_head": Color("dff6ff"),
		"pin_dark": Color("3a5670"),
		"pin_glint": Color("ffffff"),
		"petal": Color("0fa9cf"),
		"petal_light": Color("7ff0ff"),
		"pocket_trim": Color("ffe14a"),
		"panel": Color(0.04, 0.02, 0.09, 0.94),
		"panel_border": Color(0.15, 0.89, 1.0, 0.85),
		"box": Color(0.08, 0.03, 0.16),
		"box_border": Color(0.75, 0.1, 0.55),
		"title": Color("8ff3ff"),
		"title_outline": Color("4a0a5a"),
		"notes": Color("b19bd8"),
		"plate_style": FasciaPalette.PlateStyle.NEON_TUBE,
		"plate_face": Color("12051f"),
		"plate_text": Color("ff7ddc"),
	}


# Hanami: cherry blossom under a full moon and paper lanterns, black lacquer and pink.
static func _sakura() -> Dictionary:
	return {
		"art_path": ART_FOLDER + "fascia_sakura.svg",
		"art_tint": Color(0.8, 0.8, 0.84),
		"backdrop_top": Color("1c1634"),
		"backdrop_bottom": Color("07050f"),
		"plate": Color("140d1c"),
		"plate_edge": Color("2e1c36"),
		"trim": Color("d9a441"),
		"glow": Color(1.0, 0.6, 0.8, 0.05),
		"ring": Color("5a2440"),
		"ring_light": Color("f29bbd"),
		"ring_lip": Color("f7e8ee"),
		"pin_head": Color("efe0b4"),
		"pin_dark": Color("5f4a2a"),
		"pin_glint": Color("fff8e6"),
		"petal": Color("e0588f"),
		"petal_light": Color("ffb3d0"),
		"pocket_trim": Color("ffe3a0"),
		"panel": Color(0.07, 0.05, 0.11, 0.93),
		"panel_border": Color(0.95, 0.64, 0.75, 0.85),
		"box": Color(0.12, 0.08, 0.16),
		"box_border": Color(0.55, 0.35, 0.5),
		"title": Color("ffd3e2"),
		"title_outline": Color("3a0f24"),
		"notes": Color("c4a9c4"),
		"plate_style": FasciaPalette.PlateStyle.LACQUER,
		"plate_face": Color("1a1016"),
		"plate_text": Color("ffd3e2"),
	}
