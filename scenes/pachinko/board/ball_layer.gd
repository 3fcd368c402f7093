class_name BallLayer
extends Node2D
## Every ball in one draw call batch: a pre-shaded steel ball texture stamped at each
## position the world reports (no node per ball), plus the loaded ball in the launcher.
## `last_draw_usec` is how long the last draw took (the bench reads it).

const BALL_TEXTURE_SIZE := 64
## The ball texture spans this many ball diameters: room for the ball's contact shadow.
const SHADOW_SPAN := 1.6
## Balls are drawn this much larger than their physical size, so a 5 px ball is 13 px
## across at 1280 × 720 on every machine (at 1.2 they read as 6–7 px on a busy fascia). The
## physics keeps the true radius: the pins' gaps, the analysis and the replays stay as they are.
const DRAW_SCALE := 1.4

## Where the ball's dark rim begins, as a share of its radius, and its colour: a thin rim
## outlines the ball on light art without eating into the steel.
const RIM_FROM := 0.86
const RIM_COLOR := Color(0.07, 0.05, 0.12)
## The contact shadow: where it sits (a share of the ball's diameter, down and right, away
## from the light in the art's upper left), its radius (a share of the ball's) and how dark
## it is at its heart. Dark and close, so it reads on the bright fields of Windmills and
## Tulip Garden and still shows as a dark crescent on the night fascias.
const SHADOW_OFFSET := Vector2(0.2, 0.26)
const SHADOW_RADIUS := 1.0
const SHADOW_ALPHA := 0.85

# Built once per run and shared by every ball layer.
static var _shared_texture: ImageTexture

## Microseconds the last `_draw` took.
var last_draw_usec := 0
## Balls drawn by the last `_draw`.
var last_drawn := 0

var _rules: PachinkoRules
var _texture: Texture2D
var _radius := 5.0
var _launch_pos := Vector2.ZERO


## Draws the balls of `rules` (its world and its launcher).
func bind(rules: PachinkoRules) -> void:
	# the texture is stamped much smaller than it is made: mipmaps keep the ball round
	texture_filter = CanvasItem.TEXTURE_FILTER_LINEAR_WITH_MIPMAPS
	_rules = rules
	_radius = rules.level.ball_radius
	_launch_pos = LaunchRail.launch_position(rules.level)
	if _shared_texture == null:
		_shared_texture = make_shadowed_ball_texture(BALL_TEXTURE_SIZE)
	_texture = _shared_texture
	queue_redraw()


## The ball's drawn radius in board pixels (the steel disc, rim included; not the shadow).
func drawn_radius() -> float:
	return _radius * DRAW_SCALE


func _process(_delta: float) -> void:
	queue_redraw()


func _draw() -> void:
	if _rules == null:
		return
	var started := Time.get_ticks_usec()
	var positions := _rules.world.get_positions()
	var shown := _radius * DRAW_SCALE
	var size := Vector2(shown, shown) * 2.0 * SHADOW_SPAN
	var offset := Vector2(shown, shown) * SHADOW_SPAN
	for p in positions:
		draw_texture_rect(_texture, Rect2(p - offset, size), false)
	var drawn := positions.size()
	if _rules.loaded and _rules.state == PachinkoRules.State.PLAYING:
		# A slow pulse around the loaded ball, so the player sees the shot is ready.
		var pulse := 0.5 + 0.5 * sin(Time.get_ticks_msec() * 0.006)
		draw_arc(
			_launch_pos,
			_radius * 1.9,
			0.0,
			TAU,
			20,
			Color(0.5, 1.0, 0.6, 0.35 + 0.4 * pulse),
			1.5,
			true
		)
		draw_texture_rect(_texture, Rect2(_launch_pos - offset, size), false)
		drawn += 1
	last_drawn = drawn
	last_draw_usec = Time.get_ticks_usec() - started


## A steel ball: thin dark rim, a hard bright highlight at the upper left, soft reflected
## light along the lower right edge (what makes it read on the dark night fascias).
static func make_ball_texture(size: int) -> ImageTexture:
	var image := make_ball_image(size)
	image.generate_mipmaps()
	return ImageTexture.create_from_image(image)


## The ball of `size` pixels centred in a SHADOW_SPAN times larger square, over a soft
## shadow cast down and to the right (light comes from the upper left, like the art).
static func make_shadowed_ball_texture(size: int) -> ImageTexture:
	var span := int(size * SHADOW_SPAN)
	var image := Image.create_empty(span, span, false, Image.FORMAT_RGBA8)
	var centre := Vector2(span, span) * 0.5
	var shadow_at := centre + SHADOW_OFFSET * size
	var shadow_r := size * 0.5 * SHADOW_RADIUS
	for y in span:
		for x in span:
			var d := Vector2(x + 0.5, y + 0.5).distance_to(shadow_at) / shadow_r
			# dark to most of its radius, then a short soft edge
			var a := clampf((1.0 - d) / 0.45, 0.0, 1.0)
			image.set_pixel(x, y, Color(0.0, 0.0, 0.03, SHADOW_ALPHA * a * a))
	var ball := make_ball_image(size)
	@warning_ignore("integer_division")  # whole pixels: the ball sits on the texel grid
	var corner := Vector2i((span - size) / 2, (span - size) / 2)
	image.blend_rect(ball, Rect2i(Vector2i.ZERO, ball.get_size()), corner)
	image.generate_mipmaps()
	return ImageTexture.create_from_image(image)


## The ball picture itself (see make_ball_texture).
static func make_ball_image(size: int) -> Image:
	var image := Image.create_empty(size, size, false, Image.FORMAT_RGBA8)
	var centre := Vector2(size, size) * 0.5
	var radius := size * 0.5 - 1.0
	var light := centre + Vector2(-0.34, -0.38) * radius
	var bounce_at := centre + Vector2(0.3, 0.55) * radius
	for y in size:
		for x in size:
			var p := Vector2(x + 0.5, y + 0.5)
			var d := p.distance_to(centre) / radius
			if d > 1.0 + 1.0 / radius:
				image.set_pixel(x, y, Color(0, 0, 0, 0))
				continue
			var edge := clampf((1.0 - d) * radius + 0.5, 0.0, 1.0)
			var shade := lerpf(0.8, 0.34, pow(d, 1.4))
			# a small hard-edged highlight, as on polished steel
			var glint := clampf(1.0 - p.distance_to(light) / (radius * 0.34), 0.0, 1.0)
			var spec := smoothstep(0.0, 0.35, glint)
			var bounce := clampf(1.0 - p.distance_to(bounce_at) / (radius * 0.55), 0.0, 1.0)
			var v := clampf(shade + spec * 0.9 + bounce * 0.28, 0.0, 1.0)
			var steel := Color(v * 0.93, v * 0.95, v)
			# A dark rim: the ball's outline reads on light and dark art alike.
			var rim := clampf((d - RIM_FROM) / (1.0 - RIM_FROM), 0.0, 1.0)
			steel = steel.lerp(RIM_COLOR, rim * 0.85)
			image.set_pixel(x, y, Color(steel, edge))
	return image
