class_name GoldPinLayer
extends Node2D
## Draws the gold pins (GoldPins): each lit one a large gold stud with a soft pulsing glow,
## over the pins and under the balls; a pin put out bursts (a gold ring and "+1" rising);
## and while the player aims, a small white ring on each lit pin the aimed shot touches
## (PinReach: a flipper shot's power, or the handle's whole window), so which power reaches
## which gold pin is shown, not guessed. Board pixels, like the rest of the board view.

## The stud's radius (board pixels; at least the pin's own times STUD_SHARE).
const STUD_RADIUS := 5.2
const STUD_SHARE := 2.4
## The glow's reach as a multiple of the stud's radius, and its pulse (per second).
const GLOW_REACH := 3.2
const PULSE_HZ := 1.3
## A burst's length (seconds), how far its ring grows (board pixels) and its "+1"'s rise.
const BURST_SECONDS := 0.9
const BURST_REACH := 30.0
const BURST_RISE := 26.0
## The aim marker's radius as a multiple of the stud's.
const AIM_RING := 2.3
const GOLD := Color("ffc83a")
const GOLD_LIGHT := Color("fff2b0")
const GOLD_DEEP := Color("a86a00")
const GLOW := Color(1.0, 0.78, 0.2, 0.42)

var _rules: PachinkoRules
var _aim: AimPreview
var _clock := 0.0
var _stud := STUD_RADIUS
## Bursts on screen: [position, age in seconds].
var _bursts: Array[Array] = []


func _ready() -> void:
	set_process(false)


## Draws the gold pins of `rules`' game; `aim` tells which power is being aimed.
func bind(rules: PachinkoRules, aim: AimPreview) -> void:
	_rules = rules
	_aim = aim
	_bursts.clear()
	_stud = maxf(STUD_RADIUS, rules.level.pin_radius * STUD_SHARE)
	rules.gold.pin_out.connect(_on_pin_out)
	set_process(true)
	queue_redraw()


## Bursts on screen now (tests read it).
func bursts() -> int:
	return _bursts.size()


## The lit gold pins the aimed shot touches now (empty while nobody aims).
func aimed_pins() -> PackedInt32Array:
	var out := PackedInt32Array()
	if _rules == null or _aim == null or not _aim.is_showing() or _rules.gold.reach == null:
		return out
	var power := _aim.shown_power()
	var spread := 0.0 if _rules.drawing else LaunchHandle.JITTER
	var touched: Dictionary[int, bool] = {}
	var p := maxf(power - spread, 0.0)
	while p <= minf(power + spread, 100.0):
		for pin in _rules.gold.reach.pins_at(p):
			touched[pin] = true
		p += PinReach.STEP
	for pin in _rules.gold.lit_pins():
		if touched.has(pin):
			out.append(pin)
	return out


func _process(delta: float) -> void:
	_clock += delta
	for burst in _bursts:
		burst[1] += delta
	_bursts = _bursts.filter(func(b: Array) -> bool: return b[1] < BURST_SECONDS)
	queue_redraw()


func _draw() -> void:
	if _rules == null:
		return
	var pins := _rules.level.pins
	var pulse := 0.75 + 0.25 * sin(_clock * TAU * PULSE_HZ)
	for pin in _rules.gold.lit_pins():
		_draw_stud(pins[pin], pulse)
	for pin in aimed_pins():
		draw_arc(pins[pin], _stud * AIM_RING, 0.0, TAU, 28, Color(1, 1, 1, 0.9), 1.6, true)
	for burst in _bursts:
		var at: Vector2 = burst[0]
		var age: float = burst[1]
		_draw_burst(at, age / BURST_SECONDS)


func _draw_stud(at: Vector2, pulse: float) -> void:
	for ring in 4:  # the soft glow: wide and faint to small and warm
		var share := 1.0 - ring / 4.0
		var glow := Color(GLOW, GLOW.a * pulse * (1.0 - share * 0.7))
		draw_circle(at, _stud * (1.0 + (GLOW_REACH - 1.0) * share), glow)
	# a pale rim sets the stud apart from a fascia's own gold lamps (Fever's neon has many)
	draw_arc(at, _stud + 1.6, 0.0, TAU, 24, Color(1.0, 0.98, 0.9, 0.85), 1.2, true)
	draw_circle(at, _stud + 0.8, GOLD_DEEP)
	draw_circle(at, _stud, GOLD)
	draw_circle(at + Vector2(-0.3, -0.3) * _stud, _stud * 0.45, GOLD_LIGHT)


func _draw_burst(at: Vector2, t: float) -> void:
	var fade := 1.0 - t
	draw_arc(at, _stud + BURST_REACH * t, 0.0, TAU, 40, Color(GOLD_LIGHT, fade), 3.0 * fade + 1.0)
	draw_circle(at, _stud * (1.0 + t), Color(GOLD, fade * 0.6))
	var font := ThemeDB.fallback_font
	var size := 20
	var pos := at + Vector2(-9.0, -10.0 - BURST_RISE * t)
	draw_string_outline(
		font, pos, "+1", HORIZONTAL_ALIGNMENT_LEFT, -1, size, 5, Color(0.3, 0.1, 0, fade)
	)
	draw_string(font, pos, "+1", HORIZONTAL_ALIGNMENT_LEFT, -1, size, Color(GOLD_LIGHT, fade))


func _on_pin_out(pin: int, _left: int) -> void:
	_bursts.append([_rules.level.pins[pin], 0.0])
