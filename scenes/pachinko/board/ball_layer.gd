extends Node2D
## Every ball in one draw call batch: a pre-shaded steel ball texture stamped at each
## position the world reports (no node per ball), plus the loaded ball in the launcher.
## `last_draw_usec` is how long the last draw took (the bench reads it).

const BALL_TEXTURE_SIZE := 64
## The ball texture spans this many ball diameters: room for the ball's soft shadow.
const SHADOW_SPAN := 1.6
## Balls are drawn this much larger than their physical size, with a dark rim, so they
## stand out on the busy fascia (the physics keeps the true radius).
const DRAW_SCALE := 1.2

## Where the ball's dark rim begins, as a share of its radius, and its colour.
const RIM_FROM := 0.8
const RIM_COLOR := Color(0.07, 0.05, 0.12)

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
	_rules = rules
	_radius = rules.level.ball_radius
	_launch_pos = LaunchRail.launch_position(rules.level)
	if _shared_texture == null:
		_shared_texture = make_shadowed_ball_texture(BALL_TEXTURE_SIZE)
	_texture = _shared_texture
	queue_redraw()


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


## A steel ball: dark rim, bright upper-left highlight, soft reflected light below.
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
	var shadow_at := centre + Vector2(0.22, 0.3) * size
	var shadow_r := size * 0.5
	for y in span:
		for x in span:
			var d := Vector2(x + 0.5, y + 0.5).distance_to(shadow_at) / shadow_r
			var a := clampf(1.0 - d, 0.0, 1.0)
			image.set_pixel(x, y, Color(0.0, 0.0, 0.05, 0.55 * a * a))
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
	var light := centre + Vector2(-0.32, -0.36) * radius
	for y in size:
		for x in size:
			var p := Vector2(x + 0.5, y + 0.5)
			var d := p.distance_to(centre) / radius
			if d > 1.0 + 1.0 / radius:
				image.set_pixel(x, y, Color(0, 0, 0, 0))
				continue
			var edge := clampf((1.0 - d) * radius + 0.5, 0.0, 1.0)
			var shade := lerpf(0.92, 0.38, pow(d, 1.6))
			var spec := pow(clampf(1.0 - p.distance_to(light) / (radius * 0.55), 0.0, 1.0), 2.0)
			var bounce := (
				clampf(
					1.0 - p.distance_to(centre + Vector2(0.2, 0.62) * radius) / (radius * 0.5),
					0.0,
					1.0
				)
				* 0.25
			)
			var v := clampf(shade + spec * 0.9 + bounce, 0.0, 1.0)
			var steel := Color(v * 0.93, v * 0.95, v)
			# A dark rim: the ball's outline reads on light and dark art alike.
			var rim := clampf((d - RIM_FROM) / (1.0 - RIM_FROM), 0.0, 1.0)
			steel = steel.lerp(RIM_COLOR, rim * 0.85)
			image.set_pixel(x, y, Color(steel, edge))
	return image
