class_name PocketArt
extends "res://scenes/pachinko/board/board_layer.gd"
## Pocket art over each pocket's pins: a tulip in the machine's petal and trim colours
## (FasciaPalette; red and gold on Classic) whose cup covers the rim pins,
## a window showing the special pin (a gold diamond), and the payout written on it. A
## pocket glows when it catches a ball.

## Classic's pocket colours (the legend's pocket icon draws with them).
const PETAL := Color("c0283c")
const PETAL_LIGHT := Color("ee5a5f")
const GOLD := Color("f2c14e")
## Seconds a pocket's flash takes to fade.
const FLASH_SECONDS := 0.9

var _glow := PackedFloat32Array()


## Shows `level`'s pockets.
func setup(level: BoardLevel) -> void:
	_glow.resize(level.pockets.size())
	_glow.fill(0.0)
	set_process(false)
	super(level)


## How brightly pocket `index` glows now, 0..1 (1 the moment it paid out).
func glow_of(index: int) -> float:
	return _glow[index] if index >= 0 and index < _glow.size() else 0.0


## `base` as a pocket glowing `glow` (0..1) shows it: white-hot at 1, itself at 0.
static func flash_color(base: Color, glow: float) -> Color:
	return base.lerp(Color(1.0, 0.98, 0.9), 0.8 * clampf(glow, 0.0, 1.0))


## Lights pocket `index` (it just paid out).
func celebrate(index: int) -> void:
	if index >= 0 and index < _glow.size():
		_glow[index] = 1.0
		set_process(true)


func _process(delta: float) -> void:
	var any := false
	for i in _glow.size():
		_glow[i] = maxf(_glow[i] - delta / FLASH_SECONDS, 0.0)
		any = any or _glow[i] > 0.0
	queue_redraw()
	if not any:
		set_process(false)


func _draw() -> void:
	if _level == null:
		return
	for i in _level.pockets.size():
		_draw_pocket(_level.pockets[i], _glow[i] if i < _glow.size() else 0.0)


func _draw_pocket(spec: PocketSpec, glow: float) -> void:
	var half := spec.width * 0.5
	var pr := maxf(_level.pin_radius, 1.0)
	var band := pr * 2.0 + 4.0
	var top := spec.position
	var bottom_center := top + Vector2(0.0, maxf(spec.depth - half, 0.0))
	# a pocket that paid flashes: the cup goes white-hot and fades back to its colours, over
	# a gold burst and a ring thrown out from it
	var petal_color := flash_color(_palette.petal, glow)
	var gold := flash_color(_palette.pocket_trim, glow)
	if glow > 0.0:
		var reach := half + band * (1.5 + (1.0 - glow) * 3.0)
		draw_circle(bottom_center, reach, Color(1, 0.85, 0.3, 0.55 * glow))
		draw_arc(bottom_center, reach * 1.3, 0.0, TAU, 32, Color(1, 1, 0.9, glow), 3.0, true)
	# The cup: two sides and a half circle, a thick band over the rim pins.
	var rim := PackedVector2Array()
	rim.append(top + Vector2(-half, -band * 0.3))
	var steps := 14
	for s in steps + 1:
		var a := PI - PI * float(s) / float(steps)
		rim.append(bottom_center + Vector2(cos(a), sin(a)) * half)
	rim.append(top + Vector2(half, -band * 0.3))
	draw_polyline(rim, petal_color.darkened(0.4), band + 3.0, true)
	draw_polyline(rim, petal_color, band, true)
	draw_polyline(rim, _palette.petal_light, band * 0.3, true)
	# Petals flaring out from the mouth.
	for side: float in [-1.0, 1.0]:
		var root := top + Vector2(side * half, -band * 0.3)
		var petal := PackedVector2Array(
			[
				root,
				root + Vector2(side * half * 0.9, -half * 0.55),
				root + Vector2(side * half * 0.35, -half * 0.95),
				root + Vector2(-side * band * 0.2, -band * 0.6),
			]
		)
		draw_colored_polygon(petal, petal_color)
		petal.append(petal[0])
		draw_polyline(petal, gold, 1.5, true)
	# Gold leaf under the cup, and the window onto the special pin.
	var leaf_at := top + Vector2(0.0, spec.depth + pr + band * 0.6)
	var leaf := PackedVector2Array(
		[
			leaf_at + Vector2(-half * 0.9, -band * 0.4),
			leaf_at + Vector2(0.0, band * 0.9),
			leaf_at + Vector2(half * 0.9, -band * 0.4),
		]
	)
	draw_colored_polygon(leaf, gold.darkened(0.15))
	var special := PocketStamp.special_position(spec)
	draw_circle(special, pr * 2.6, Color(0.05, 0.02, 0.1, 0.85))
	PinArt.draw_special(self, special, pr)
	# The payout on a dark tag above the petals.
	var font := ThemeDB.fallback_font
	var text := "×%d" % spec.payout
	var font_size := int(clampf(half * 1.1, 11.0, 22.0))
	var text_size := font.get_string_size(text, HORIZONTAL_ALIGNMENT_LEFT, -1, font_size)
	var base := top + Vector2(-text_size.x * 0.5, -half * 1.05 - 4.0)
	var tag := Rect2(base + Vector2(-3.0, -text_size.y * 0.78), text_size + Vector2(6.0, 1.0))
	draw_rect(tag, Color(0.08, 0.02, 0.06, 0.8))
	draw_string(font, base, text, HORIZONTAL_ALIGNMENT_LEFT, -1, font_size, gold.lightened(0.3))
