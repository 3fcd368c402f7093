class_name PinLights
extends Node2D
## Pins light up where something strikes them, in the colour of what struck them: a warm
## glow for a ball, a hot pink one for a ball in a fever round, and whatever colour a bonus
## effect asks for (`light`: a pocket's catch, the jackpot's sweep). A glow fades over
## FADE_SECONDS, brighter for a harder hit. One canvas item draws every lit pin in one pass
## (no node per pin), with additive blending, and it sleeps while nothing is lit.

## Seconds a full-strength flash takes to fade out (long enough to see where a ball went).
const FADE_SECONDS := 0.6
## A flash's outer glow, as a multiple of the lit pin's radius: about 20 board pixels across
## for Classic's pins, 19 px on screen at 1280 × 720.
const HALO_REACH := 4.5
## The ring a flash throws out grows to this multiple of the pin's radius as it fades.
const RING_REACH := 5.5
## A flash that stays pin-sized (the jackpot's sweep, a whole column at once: trial 6 saw
## the full halo on every pin as big white discs), as a multiple of the pin's radius.
const PIN_SIZED_REACH := 1.6
## Impact speed (px/s) that lights a pin fully; softer taps glow less (never under MIN_GLOW).
const FULL_SPEED := 320.0
const MIN_GLOW := 0.35
## A ball's strike.
const GLOW := Color(1.0, 0.82, 0.42)
## A ball's strike while an attacker is open (fever).
const FEVER_GLOW := Color(1.0, 0.36, 0.62)
const CORE := Color(1.0, 0.97, 0.85)

## Pins lit at the last draw (tests and the bench read it).
var last_lit := 0

## The board's pins, then every bonus pocket's rim pins: the world's pin order.
var _pins := PackedVector2Array()
## The world pocket id of each pin (-1: a field pin).
var _pocket_of := PackedInt32Array()
var _glow := PackedFloat32Array()
var _tint := PackedColorArray()
# Each lit pin's flash reach (a multiple of _radius): HALO_REACH, or PIN_SIZED_REACH.
var _reach := PackedFloat32Array()
var _lit := PackedInt32Array()
var _radius := 2.2
var _machine: BonusMachine


func _ready() -> void:
	var additive := CanvasItemMaterial.new()
	additive.blend_mode = CanvasItemMaterial.BLEND_MODE_ADD
	material = additive
	set_process(false)


## Lights the pins of `rules`' world as balls hit them.
func bind(rules: PachinkoRules) -> void:
	var level := rules.level
	_machine = rules.bonus
	_pins = level.pins.duplicate()
	_pocket_of = level.pin_pocket.duplicate()
	_pocket_of.resize(_pins.size())
	for i in level.bonus_pockets.size():
		var rim := BonusGeometry.rim_pins(level, level.bonus_pockets[i])
		_pins.append_array(rim)
		for k in rim.size():
			_pocket_of.append(BonusGeometry.pocket_id(level, i))
	_radius = maxf(level.pin_radius + 0.8, 2.2)
	_glow = PackedFloat32Array()
	_glow.resize(_pins.size())
	_tint = PackedColorArray()
	_tint.resize(_pins.size())
	_reach = PackedFloat32Array()
	_reach.resize(_pins.size())
	_lit = PackedInt32Array()
	rules.world.pin_hit.connect(_on_pin_hit)
	queue_redraw()


## How far a flash reaches from its pin's centre at full strength, in board pixels.
func flash_reach() -> float:
	return _radius * maxf(HALO_REACH, RING_REACH)


## How brightly pin `index` glows now, 0..1.
func glow_of(index: int) -> float:
	return _glow[index] if index >= 0 and index < _glow.size() else 0.0


## The colour pin `index` glows in (meaningful while it glows).
func tint_of(index: int) -> Color:
	return _tint[index] if index >= 0 and index < _tint.size() else Color.BLACK


## Pins this layer can light (the world's pins).
func pin_count() -> int:
	return _pins.size()


## Where pin `index` is, in board pixels.
func pin_position(index: int) -> Vector2:
	return _pins[index]


## How far pin `index`'s flash reaches from its centre now, in board pixels (0: unlit).
func flash_reach_of(index: int) -> float:
	if glow_of(index) <= 0.0:
		return 0.0
	return _radius * (_reach[index] if _reach[index] < HALO_REACH else flash_reach() / _radius)


## Lights pin `index` in `tint` at `strength` (0..1); a brighter glow already there stays.
## `pin_sized`: no halo or ring, a pin-sized flash (many pins lit at once).
func light(index: int, tint: Color, strength: float, pin_sized := false) -> void:
	if index < 0 or index >= _glow.size() or strength <= 0.0:
		return
	if _glow[index] <= 0.0:
		_lit.append(index)
	if strength >= _glow[index]:
		_tint[index] = tint
		_reach[index] = PIN_SIZED_REACH if pin_sized else HALO_REACH
	_glow[index] = maxf(_glow[index], minf(strength, 1.0))
	set_process(true)


## Lights every rim pin of world pocket `pocket_id` in `tint` (the pocket caught a ball).
func light_pocket(pocket_id: int, tint: Color) -> void:
	for pin in _pocket_of.size():
		if _pocket_of[pin] == pocket_id:
			light(pin, tint, 1.0)


func _on_pin_hit(_ball: int, pin: int, speed: float) -> void:
	var fever := _machine != null and _machine.any_attacker_open()
	light(pin, FEVER_GLOW if fever else GLOW, clampf(speed / FULL_SPEED, MIN_GLOW, 1.0))


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
		var tint := _tint[pin]
		if _reach[pin] < HALO_REACH:
			draw_circle(p, _radius * _reach[pin], Color(CORE.lerp(tint, 0.3), 0.85 * a))
			continue
		draw_circle(p, _radius * HALO_REACH, Color(tint, 0.4 * a))
		draw_circle(p, _radius * 2.6, Color(tint, 0.8 * a))
		draw_circle(p, _radius * 1.4, Color(CORE.lerp(tint, 0.2), a))
		# a ring thrown out from the pin: the eye catches the motion on busy art
		var ring := lerpf(2.0, RING_REACH, 1.0 - a)
		draw_arc(p, _radius * ring, 0.0, TAU, 16, Color(CORE, a), 1.5, true)
	last_lit = _lit.size()
