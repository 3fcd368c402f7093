class_name BoardView
extends Node2D
## The board in layers, bottom to top as in the chapter: back plate, fascia art, ring
## border and name plate, launch path, gutter, pins, balls, pocket art, effects. The board's
## machine (`fascia`, FasciaBook) picks the art and every layer's colours. `bind()` hands each layer
## the board; `fit()` scales the whole board into a rectangle of the screen.
##
## The layers that never change (plate, fascia, ring, rail, gutter slot, pins) are drawn
## once into an off-screen viewport at the board's on-screen resolution and shown as one
## texture, so a frame only draws that texture, the balls, the pockets and the effects.

const FASCIA_SIZE := 1000.0
## How far the plate reaches beyond the ring, as a share of the ring radius.
const PLATE_REACH := 1.1
## Extra room around the plate for its shadow, in board pixels.
const PLATE_MARGIN := 12.0
## The bake never exceeds this many pixels a side.
const MAX_BAKE := 4096

## Screen pixels the board is pushed off its fitted place (a camera nudge; zero at rest).
var nudge := Vector2.ZERO:
	set(value):
		nudge = value
		position = _fitted_position + nudge

var _level: BoardLevel
var _bake_scale := 0.0
var _fitted_position := Vector2.ZERO

@onready var bake: SubViewport = $Bake
@onready var static_root: Node2D = $Bake/Static
@onready var baked: Sprite2D = $Baked
@onready var backplate: BoardLayer = $Bake/Static/Backplate
@onready var fascia: Sprite2D = $Bake/Static/Fascia
@onready var ring_border: BoardLayer = $Bake/Static/RingBorder
@onready var launch_path: BoardLayer = $Bake/Static/LaunchPath
@onready var gutter_slot: GutterArt = $Bake/Static/Gutter
@onready var pins: BoardLayer = $Bake/Static/Pins
@onready var gutter: GutterArt = $GutterFlash
@onready var balls: BallLayer = $Balls
@onready var pockets: PocketArt = $Pockets
@onready var effects: WinEffects = $Effects


## Shows the board and balls of `rules`.
func bind(rules: PachinkoRules) -> void:
	var level := rules.level
	_level = level
	var layers: Array[BoardLayer] = [
		backplate, ring_border, launch_path, gutter_slot, pins, gutter, pockets
	]
	for layer in layers:
		layer.setup(level)
	balls.bind(rules)
	_pin_lights().bind(rules)
	_windmill_layer().bind(rules)
	aim_preview().bind(rules)
	_dress(level)
	_bake_scale = 0.0
	_rebake()


# The machine the board wears (FasciaBook): its art behind the pins and its name plate.
func _dress(level: BoardLevel) -> void:
	var palette := FasciaBook.palette_of(level.fascia)
	fascia.texture = FasciaBook.art_of(palette)
	fascia.modulate = palette.art_tint
	fascia.position = level.ring_center
	fascia.scale = Vector2.ONE * (level.ring_radius * 2.0 / FASCIA_SIZE)
	var plate := static_root.get_node_or_null(^"NamePlate") as NamePlateLayer
	if plate == null:
		plate = NamePlateLayer.new()
		plate.name = "NamePlate"
		static_root.add_child(plate)
		static_root.move_child(plate, ring_border.get_index() + 1)
	plate.setup(level)


## The pin flashes (made by the first `bind`), for effects that light pins.
func pin_lights() -> PinLights:
	return _pin_lights()


## The pin flashes, made on first use and drawn under the balls.
func _pin_lights() -> PinLights:
	var lights := get_node_or_null(^"PinLights") as PinLights
	if lights == null:
		lights = PinLights.new()
		lights.name = "PinLights"
		add_child(lights)
		move_child(lights, balls.get_index())
	return lights


## The aim preview (where a shot at the power being aimed flies), made on first use and
## drawn over the balls.
func aim_preview() -> AimPreview:
	var layer := get_node_or_null(^"AimPreview") as AimPreview
	if layer == null:
		layer = AimPreview.new()
		layer.name = "AimPreview"
		add_child(layer)
		move_child(layer, balls.get_index() + 1)
	return layer


## The turning windmills, made on first use and drawn under the balls (above the pin lights).
func _windmill_layer() -> WindmillLayer:
	var layer := get_node_or_null(^"Windmills") as WindmillLayer
	if layer == null:
		layer = WindmillLayer.new()
		layer.name = "Windmills"
		add_child(layer)
		move_child(layer, balls.get_index())
	return layer


## Scales and places the board so its plate fills `area` (screen pixels), centred.
func fit(level: BoardLevel, area: Rect2) -> void:
	var half := level.ring_radius * PLATE_REACH + PLATE_MARGIN
	var board_scale := minf(area.size.x, area.size.y) / (half * 2.0)
	scale = Vector2.ONE * board_scale
	_fitted_position = area.get_center() - level.ring_center * board_scale
	position = _fitted_position + nudge
	_rebake()


## The screen point of a board point (the fitted place, without a shake's nudge).
func to_screen(board: Vector2) -> Vector2:
	return _fitted_position + board * scale.x


## Board coordinates of a screen point.
func to_board(screen: Vector2) -> Vector2:
	return (screen - position) / scale.x


## The board rectangle the bake covers (plate, shadow and margin), in board pixels.
func bake_rect() -> Rect2:
	if _level == null:
		return Rect2()
	var half := _level.ring_radius * PLATE_REACH + PLATE_MARGIN + 12.0
	return Rect2(_level.ring_center - Vector2(half, half), Vector2(half, half) * 2.0)


# Redraws the static layers into the bake at one texel per screen pixel.
func _rebake() -> void:
	if _level == null or not is_inside_tree():
		return
	if baked.texture == null:
		baked.texture = bake.get_texture()
	var screen_scale := scale.x * _stretch_scale()
	var rect := bake_rect()
	var side := rect.size.x * screen_scale
	if side > MAX_BAKE:
		screen_scale *= MAX_BAKE / side
	if is_equal_approx(screen_scale, _bake_scale):
		return
	_bake_scale = screen_scale
	bake.size = Vector2i(ceili(rect.size.x * screen_scale), ceili(rect.size.y * screen_scale))
	static_root.scale = Vector2.ONE * screen_scale
	static_root.position = -rect.position * screen_scale
	baked.position = rect.position
	baked.scale = Vector2.ONE / screen_scale
	bake.render_target_update_mode = SubViewport.UPDATE_ONCE


# Window pixels per viewport pixel (the canvas_items stretch).
func _stretch_scale() -> float:
	var viewport := get_viewport()
	if viewport == null:
		return 1.0
	var shown := viewport.get_visible_rect().size
	var window := Vector2(viewport.get_window().size) if viewport.get_window() != null else shown
	if shown.y <= 0.0:
		return 1.0
	return maxf(window.y / shown.y, 0.25)
