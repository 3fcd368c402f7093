extends Node2D
## Pins light up where balls strike them: a warm glow that fades over FADE_SECONDS, brighter
## for a harder hit. One canvas item draws every lit pin in one pass (no node per pin), with
## additive blending, and it sleeps while nothing is lit.

## Seconds a full-strength flash takes to fade out.
const FADE_SECONDS := 0.45
## Impact speed (px/s) that lights a pin fully; softer taps glow less (never under MIN_GLOW).
const FULL_SPEED := 320.0
const MIN_GLOW := 0.35
const GLOW := Color(1.0, 0.82, 0.42)
const CORE := Color(1.0, 0.97, 0.85)

## Pins lit at the last draw (tests and the bench read it).
var last_lit := 0

var _pins := PackedVector2Array()
var _glow := PackedFloat32Array()
var _lit := PackedInt32Array()
var _radius := 2.2


func _ready() -> void:
	var additive := CanvasItemMaterial.new()
	additive.blend_mode = CanvasItemMaterial.BLEND_MODE_ADD
	material = additive
	set_process(false)


## Lights the pins of `rules`' world as balls hit them.
func bind(rules: PachinkoRules) -> void:
	_pins = rules.level.pins
	_radius = maxf(rules.level.pin_radius + 0.8, 2.2)
	_glow = PackedFloat32Array()
	_glow.resize(_pins.size())
	_lit = PackedInt32Array()
	rules.world.pin_hit.connect(_on_pin_hit)
	queue_redraw()


## How brightly pin `index` glows now, 0..1.
func glow_of(index: int) -> float:
	return _glow[index] if index >= 0 and index < _glow.size() else 0.0


func _on_pin_hit(_ball: int, pin: int, speed: float) -> void:
	if pin < 0 or pin >= _glow.size():
		return
	if _glow[pin] <= 0.0:
		_lit.append(pin)
	_glow[pin] = maxf(_glow[pin], clampf(speed / FULL_SPEED, MIN_GLOW, 1.0))
	set_process(true)


func _process(delta: float) -> void:
	var still := PackedInt32Array()
	for pin in _lit:
		_glow[pin] = maxf(_glow[pin] - delta / FADE_SECONDS, 0.0)
		if _glow[pin] > 0.0:
			still.append(pin)
	_lit = still
	queue_redraw()
	if _lit.is_empty():
		set_process(false)


func _draw() -> void:
	for pin in _lit:
		var a := _glow[pin]
		var p := _pins[pin]
		draw_circle(p, _radius * 4.5, Color(GLOW, 0.25 * a))
		draw_circle(p, _radius * 2.6, Color(GLOW, 0.55 * a))
		draw_circle(p, _radius * 1.3, Color(CORE, a))
	last_lit = _lit.size()
