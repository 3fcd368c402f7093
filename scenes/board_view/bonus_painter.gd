class_name BonusPainter
extends RefCounted
## Draws one bonus pocket on any canvas: its cup, rim pins and catching pin, its lid or
## wings in their current state, a lamp that glows with `light` (0..1) and its label.
## The game's bonus art draws the live state with it; the board painter (menus, editor)
## draws every bonus pocket closed.

## Cup colours per role (start pocket, attacker, tulip).
const CUP_COLORS: Array[Color] = [Color("1f7a5a"), Color("8c1d2c"), Color("b8417a")]
const LAMP_COLORS: Array[Color] = [Color("6dffb9"), Color("ffcf4a"), Color("ff9ad5")]
const LABELS: Array[String] = ["START", "ATTACKER", ""]
## The labels' font size (board pixels), the room around them and their tag's colour.
const LABEL_SIZE := 10
const LABEL_PAD := 2.0
const LABEL_TAG := Color(0.05, 0.02, 0.08, 0.88)
const LID := Color("d9a640")
const PETAL := Color("f07ab4")
const PETAL_EDGE := Color("5c1538")


## Every bonus pocket of `level`, closed and unlit.
static func draw_all(canvas: CanvasItem, level: BoardLevel) -> void:
	for spec in level.bonus_pockets:
		if _drawable(spec):
			draw_pocket(canvas, level, spec, false, 0.0)


## One bonus pocket; `open` is its lid or wings' state, `light` its lamp (0..1);
## `openness` (0 shut .. 1 open), when given, is where a tulip's swinging wings are now.
static func draw_pocket(
	canvas: CanvasItem,
	level: BoardLevel,
	spec: BonusPocketSpec,
	open: bool,
	light: float,
	openness: float = -1.0
) -> void:
	var half := spec.width * 0.5
	var cup_color := CUP_COLORS[spec.role]
	var lamp := LAMP_COLORS[spec.role]
	var body := Rect2(
		spec.position - Vector2(half + 5.0, 2.0), Vector2(spec.width + 10.0, spec.depth + 8.0)
	)
	if light > 0.0:
		canvas.draw_circle(
			body.get_center(), maxf(body.size.x, body.size.y) * 0.9, Color(lamp, 0.35 * light)
		)
	canvas.draw_rect(body, Color(cup_color, 0.85))
	canvas.draw_rect(body, Color(lamp, 0.4 + 0.6 * light), false, 1.5)
	_draw_rim(canvas, level, spec)
	match spec.role:
		BonusPocketSpec.Role.ATTACKER:
			_draw_lid(canvas, spec, open)
		BonusPocketSpec.Role.TULIP:
			var amount := openness if openness >= 0.0 else (1.0 if open else 0.0)
			_draw_wings(canvas, level, spec, amount)
	var label := LABELS[spec.role]
	if not label.is_empty():
		# on a dark tag of its own: trial 7 could not read Hanami's ATTACKER over the blossoms
		var tag := label_rect(spec)
		canvas.draw_rect(tag, LABEL_TAG)
		var font := ThemeDB.fallback_font
		var at := Vector2(tag.position.x + LABEL_PAD, tag.end.y - LABEL_PAD - 1.0)
		canvas.draw_string(
			font,
			at,
			label,
			HORIZONTAL_ALIGNMENT_LEFT,
			-1,
			LABEL_SIZE,
			lamp.lerp(Color.WHITE, light)
		)


## The dark tag under bonus pocket `spec` that carries its label ("START", "ATTACKER"), board
## pixels; empty for a piece without one (a tulip).
static func label_rect(spec: BonusPocketSpec) -> Rect2:
	var label := LABELS[spec.role]
	if label.is_empty():
		return Rect2()
	var font := ThemeDB.fallback_font
	var text := font.get_string_size(label, HORIZONTAL_ALIGNMENT_LEFT, -1, LABEL_SIZE)
	var size := Vector2(text.x, font.get_ascent(LABEL_SIZE)) + Vector2.ONE * LABEL_PAD * 2.0
	var top := spec.position.y + spec.depth + 7.0  # just under the cup's body
	return Rect2(Vector2(spec.position.x - size.x * 0.5, top), size)


static func _draw_rim(canvas: CanvasItem, level: BoardLevel, spec: BonusPocketSpec) -> void:
	var pins := BonusGeometry.rim_pins(level, spec)
	var r := maxf(level.pin_radius + 0.8, 2.2)
	for k in pins.size():
		if k == pins.size() - 1:
			PinArt.draw_special(canvas, pins[k], r)
		else:
			canvas.draw_circle(pins[k], r + 0.6, Color(0.05, 0.03, 0.08, 0.8))
			canvas.draw_circle(pins[k], r, PinArt.HEAD)


# Closed: a gold roof across the mouth (the world's two lid halves). Open: the two halves
# swung up on their hinges.
static func _draw_lid(canvas: CanvasItem, spec: BonusPocketSpec, open: bool) -> void:
	var half := spec.width * 0.5
	var left := spec.position + Vector2(-half, 0.0)
	var right := spec.position + Vector2(half, 0.0)
	var width := BonusGeometry.PART_RADIUS * 2.0 + 1.0
	if not open:
		var roof := PackedVector2Array([left, BonusGeometry.lid_ridge(spec), right])
		canvas.draw_polyline(roof, Color(0.1, 0.05, 0.0), width + 2.0, true)
		canvas.draw_polyline(roof, LID, width, true)
		return
	var flap := half * 0.8
	for side: float in [-1.0, 1.0]:
		var hinge := left if side < 0.0 else right
		var tip := hinge + Vector2(side * flap * 0.35, -flap)
		canvas.draw_line(hinge, tip, Color(0.1, 0.05, 0.0), width + 2.0, true)
		canvas.draw_line(hinge, tip, LID.lightened(0.3), width, true)


# The wings as petals, where the world has them `openness` open (upright shut, spread
# open, between while they swing).
static func _draw_wings(
	canvas: CanvasItem, level: BoardLevel, spec: BonusPocketSpec, openness: float
) -> void:
	var index := level.bonus_pockets.find(spec)
	for wing in BonusGeometry.petal_plan(level):
		if wing["item"] != index:
			continue
		var a: Vector2 = wing["hinge"]
		var b := BonusGeometry.petal_tip(wing, openness)
		var across := (b - a).orthogonal().normalized() * 3.5
		var mid := a.lerp(b, 0.55)
		var petal := PackedVector2Array([a, mid + across, b, mid - across])
		canvas.draw_colored_polygon(petal, PETAL)
		petal.append(a)
		canvas.draw_polyline(petal, PETAL_EDGE, 1.2, true)


# A pocket being edited may hold any value: only a sane one is drawn.
static func _drawable(spec: BonusPocketSpec) -> bool:
	if spec == null or not spec.position.is_finite():
		return false
	if not is_finite(spec.width) or not is_finite(spec.depth) or spec.width <= 0.0:
		return false
	return spec.width <= 1000.0 and spec.depth <= 1000.0 and spec.depth >= spec.width * 0.5
