class_name LightSweep
extends Node2D
## The jackpot's light sweep: a band of light runs across the field from the upper left to
## the lower right in SECONDS, like a lamp passing behind the glass, and every pin it
## crosses flashes white-gold (PinLights). Drawn additive over the balls, clipped to the
## ring; one polygon pair a frame while it runs, asleep otherwise.

## Real seconds for the band to cross the field.
const SECONDS := 0.9
## Half the band's width, as a share of the ring radius.
const HALF_WIDTH := 0.22
## The direction the band travels (it lies across it).
const TRAVEL := Vector2(1.0, 0.45)
const LIGHT := Color(1.0, 0.93, 0.7)
## How bright the band is at its centre line (additive).
const PEAK := 0.42
## The pins' flash as the band's centre passes them.
const PIN_TINT := Color(1.0, 0.96, 0.82)

var _centre := Vector2.ZERO
var _radius := 0.0
var _ring := PackedVector2Array()
var _age := SECONDS
var _front := -INF
## Each pin's distance along TRAVEL from the ring centre.
var _pin_reach := PackedFloat32Array()
var _lights: PinLights
var _sounds: SoundBank


func _ready() -> void:
	var additive := CanvasItemMaterial.new()
	additive.blend_mode = CanvasItemMaterial.BLEND_MODE_ADD
	material = additive
	set_process(false)


## Sweeps over `level`'s field, flashing the pins of `lights` (null: no pin flashes) and
## playing the shimmer on `sounds` (null: silent).
func bind(level: BoardLevel, lights: PinLights, sounds: SoundBank) -> void:
	_centre = level.ring_center
	_radius = level.ring_radius
	_lights = lights
	_sounds = sounds
	_ring = PackedVector2Array()
	for i in 64:
		_ring.append(_centre + Vector2.from_angle(TAU * i / 64.0) * _radius)
	_age = SECONDS
	set_process(false)
	queue_redraw()


## Starts a sweep (a jackpot).
func start() -> void:
	if _radius <= 0.0:
		return
	_pin_reach = PackedFloat32Array()
	if _lights != null:
		var along := TRAVEL.normalized()
		for i in _lights.pin_count():
			_pin_reach.append((_lights.pin_position(i) - _centre).dot(along))
	_age = 0.0
	_front = -INF
	set_process(true)
	if _sounds != null:
		_sounds.play(SoundBank.LIGHT_SWEEP, -5.0)


## True while the band is on the field.
func is_sweeping() -> bool:
	return _age < SECONDS


## Where the band's centre line lies now, along TRAVEL from the ring centre.
func band_reach() -> float:
	var half := _radius * HALF_WIDTH
	return lerpf(-_radius - half, _radius + half, clampf(_age / SECONDS, 0.0, 1.0))


func _process(delta: float) -> void:
	_age += delta
	var reach := band_reach()
	if _lights != null:
		for i in _pin_reach.size():
			if _pin_reach[i] > _front and _pin_reach[i] <= reach:
				_lights.light(i, PIN_TINT, 1.0, true)  # pin-sized: a column lights at once
	_front = reach
	queue_redraw()
	if not is_sweeping():
		set_process(false)


func _draw() -> void:
	if not is_sweeping():
		return
	var along := TRAVEL.normalized()
	var across := along.orthogonal() * _radius * 1.2
	var middle := _centre + along * band_reach()
	var half := along * _radius * HALF_WIDTH
	# Two halves, bright on the centre line and dark at the edges; colours follow the
	# distance from the line, which draw_polygon shades smoothly between the corners.
	for edge: Vector2 in [half, -half]:
		var quad := PackedVector2Array(
			[middle - across, middle + across, middle + across + edge, middle - across + edge]
		)
		for piece in Geometry2D.intersect_polygons(quad, _ring):
			var colours := PackedColorArray()
			for point in piece:
				var off := absf((point - middle).dot(along)) / half.length()
				colours.append(Color(LIGHT, PEAK * clampf(1.0 - off, 0.0, 1.0)))
			draw_polygon(piece, colours)
