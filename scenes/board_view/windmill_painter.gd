class_name WindmillPainter
extends RefCounted
## Draws a windmill (WindmillSpec) at a given blade angle, as the pinwheel of a real
## machine: a coloured sail behind each brass blade, round tips, a hub with the pin in its
## middle. Only the blades are solid (the world's capsules); the sails are thin see-through
## film, so the pins and balls behind them still show (a play trial read the bare blades
## as "small gold crosses, not windmills"). The game's windmill layer draws each wheel at
## the world's angle every frame; BoardPainter draws them at rest for the menus and the
## editor. A free wheel's hub is brass, a driven one's red, so the two read apart at a glance.

const BLADE_COLOR := Color("e9cf8a")
const BLADE_EDGE := Color("6b4a1c")
const DRIVEN_HUB := Color("d2453a")
const FREE_HUB := Color("c99a3e")
const PIN_COLOR := Color("f3f1ea")
## The hub's radius as a share of the blade length (never smaller than a blade).
const HUB_SHARE := 0.22
## The sails' colours, blade by blade, as a toy pinwheel's.
const SAIL_COLORS: Array[Color] = [
	Color(0.93, 0.26, 0.23, 0.55),
	Color(0.99, 0.80, 0.20, 0.55),
	Color(0.22, 0.56, 0.92, 0.55),
	Color(0.30, 0.78, 0.38, 0.55),
]
## How far round from its blade a sail reaches (radians), and how far out its outer corner
## sits (a share of the blade length).
const SAIL_SPREAD := 0.62
const SAIL_REACH := 0.78


## Draws `spec` on `canvas` (inside its `_draw`) with blade 0 at `angle` radians (y down).
static func draw_wheel(canvas: CanvasItem, spec: WindmillSpec, angle: float) -> void:
	if spec == null or not spec.position.is_finite() or not is_finite(spec.length):
		return
	var c := spec.position
	var count := clampi(spec.blades, 1, WindmillSpec.BLADES_RANGE.y)
	var r := WindmillSpec.BLADE_RADIUS
	var pitch := TAU / float(count)
	var spread := minf(SAIL_SPREAD, pitch * 0.7)
	for k in count:
		# a sail: from the hub along the blade to its tip, back to a corner behind it
		var along := angle + pitch * k
		var sail := PackedVector2Array(
			[
				c,
				c + Vector2.from_angle(along) * spec.length,
				c + Vector2.from_angle(along - spread) * spec.length * SAIL_REACH,
			]
		)
		var color := SAIL_COLORS[k % SAIL_COLORS.size()]
		canvas.draw_colored_polygon(sail, color)
		canvas.draw_polyline(sail, color.darkened(0.45), 1.0, true)
	for k in count:
		var tip := c + Vector2.from_angle(angle + pitch * k) * spec.length
		canvas.draw_line(c, tip, BLADE_EDGE, r * 2.0 + 1.0)
		canvas.draw_circle(tip, r + 0.5, BLADE_EDGE)
	for k in count:
		var tip := c + Vector2.from_angle(angle + pitch * k) * spec.length
		canvas.draw_line(c, tip, BLADE_COLOR, r * 2.0 - 0.6)
		canvas.draw_circle(tip, r - 0.3, BLADE_COLOR)
	var hub := maxf(spec.length * HUB_SHARE, r * 1.5)
	canvas.draw_circle(c, hub + 0.8, BLADE_EDGE)
	canvas.draw_circle(c, hub, FREE_HUB if spec.free_spin else DRIVEN_HUB)
	canvas.draw_circle(c, maxf(hub * 0.35, 1.0), PIN_COLOR)
