class_name MazeBallMaterial
extends RefCounted
## The maze balls' surface for each look: the tutorial's glossy red, the wood look's polished
## steel, and Low graphics' satin steel (split out of MazeStage, which places the balls); and
## for the steel looks a dark rim round each ball.
##
## Trial 8 kept losing the steel balls on the pale maple of the bigger boards: the steel's
## colour (luminance 0.80) was the maple's (0.80). The steel is now a dark gunmetal and a
## thin dark rim sets each ball off the floor, whatever the light on it.

## The steel's colour (luminance about 0.36, the maple's 0.80).
const STEEL := Color(0.42, 0.44, 0.48)
## Its own glow, darkened, so the ball is not black in the shade of a wall.
const STEEL_GLOW := Color(0.3, 0.31, 0.34)
## The rim's colour and its width, a part of the ball's radius.
const RIM := Color(0.07, 0.06, 0.06)
const RIM_WIDTH := 0.18


## The balls' surface: the seed's glossy red-orange (the tutorial's look), or polished steel
## (with `low` graphics a satin steel that needs no reflections to read as metal).
static func make(seed_red: bool, low := false) -> StandardMaterial3D:
	var mat := StandardMaterial3D.new()
	mat.albedo_texture = _ball_band_texture(MazePalette.BALL if seed_red else STEEL)
	# a little glow of its own, so the ball stays as bright as the seed's beside the floor
	mat.emission_enabled = true
	mat.emission = (MazePalette.BALL if seed_red else STEEL_GLOW).darkened(0.4)
	mat.emission_energy_multiplier = 0.6
	if seed_red:
		mat.roughness = 0.28
		mat.metallic_specular = 0.7
	elif low:
		# no room to reflect: a bright satin grey with the sun's highlight, lit per vertex
		# (software GL lights every pixel of a ball otherwise)
		mat.shading_mode = BaseMaterial3D.SHADING_MODE_PER_VERTEX
		mat.roughness = 0.3
		mat.metallic_specular = 0.8
		mat.emission_energy_multiplier = 0.9
	else:
		# polished: the room (room_panorama) shows in it; less glow of its own
		mat.metallic = 0.95
		mat.roughness = 0.14
		mat.emission_energy_multiplier = 0.3
	return mat


## The dark rim drawn round each steel ball (null for the tutorial's red balls, which stand
## out on its white board): the ball's own sphere drawn grown by RIM_WIDTH, unlit, with its
## front faces culled, so only a ring shows past the ball's edge. Costs one unlit sphere a
## ball, in Low graphics too.
static func rim(seed_red: bool) -> StandardMaterial3D:
	if seed_red:
		return null
	var mat := StandardMaterial3D.new()
	mat.shading_mode = BaseMaterial3D.SHADING_MODE_UNSHADED
	mat.albedo_color = RIM
	mat.cull_mode = BaseMaterial3D.CULL_FRONT
	return mat


# A ball texture with a faint band round its equator, so the roll can be seen.
static func _ball_band_texture(colour: Color) -> ImageTexture:
	var image := Image.create(64, 32, false, Image.FORMAT_RGB8)
	var band := colour.darkened(0.22)
	for y in 32:
		var v := absf((float(y) + 0.5) / 32.0 - 0.5)
		var c := band if v < 0.045 else colour
		for x in 64:
			image.set_pixel(x, y, c)
	return ImageTexture.create_from_image(image)
