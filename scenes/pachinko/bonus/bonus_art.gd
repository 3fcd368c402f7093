class_name BonusArt
extends Node2D
## The live bonus pockets over the board: each cup with its lid or wings as the world has
## them, a lamp that flashes when it catches a ball and glows while an attacker is open,
## and an open attacker's seconds and catches left. Reads BonusMachine; never changes it.

## Seconds a catch keeps a lamp lit.
const FLASH_SECONDS := 0.8
## The countdown's font size and the room round it on its plaque (board pixels).
const COUNTDOWN_SIZE := 13
const COUNTDOWN_PAD := Vector2(6.0, 3.0)
## The countdown's z: over the board's other pieces (the start pocket, the beacon's chevrons),
## which cut a play trial's "8 s left" in two.
const COUNTDOWN_Z := 90

var _level: BoardLevel
var _machine: BonusMachine
var _light := PackedFloat32Array()
var _clock := 0.0
## The open attackers' countdowns: a layer of their own, over the board's other pieces.
var _countdowns := Node2D.new()


func _init() -> void:
	_countdowns.name = "Countdowns"
	_countdowns.z_index = COUNTDOWN_Z
	_countdowns.draw.connect(_draw_countdowns)
	add_child(_countdowns)


## Shows the bonus pockets of `level` as `machine` runs them.
func bind(level: BoardLevel, machine: BonusMachine) -> void:
	_level = level
	_machine = machine
	_light.resize(level.bonus_pockets.size())
	_light.fill(0.0)
	set_process(machine.has_bonus())
	visible = machine.has_bonus()
	queue_redraw()


## Lights bonus pocket `index` (it caught a ball).
func flash(index: int) -> void:
	if index >= 0 and index < _light.size():
		_light[index] = 1.0


func _process(delta: float) -> void:
	_clock += delta
	for i in _light.size():
		_light[i] = maxf(_light[i] - delta / FLASH_SECONDS, 0.0)
	queue_redraw()
	_countdowns.queue_redraw()


func _draw() -> void:
	if _level == null or _machine == null:
		return
	for i in _level.bonus_pockets.size():
		var spec := _level.bonus_pockets[i]
		var open := _machine.is_open(i)
		var light := _light[i]
		if open and spec.role == BonusPocketSpec.Role.ATTACKER:
			light = maxf(light, 0.6 + 0.4 * sin(_clock * 12.0))
		BonusPainter.draw_pocket(self, _level, spec, open, light, _machine.openness(i))


## The countdowns' layer (for tests: drawn over the board's other pieces).
func countdown_layer() -> Node2D:
	return _countdowns


## What the countdown under open attacker `index` says ("8 s · 10 left").
func countdown_text(index: int) -> String:
	return "%.0f s · %d left" % [ceilf(_machine.time_left(index)), _machine.catches_left(index)]


## The countdown's plaque under attacker `index` (board pixels): one piece, under the cup,
## clear of the start pocket above it.
func countdown_rect(index: int) -> Rect2:
	var spec := _level.bonus_pockets[index]
	var font := ThemeDB.fallback_font
	var text_size := font.get_string_size(
		countdown_text(index), HORIZONTAL_ALIGNMENT_LEFT, -1, COUNTDOWN_SIZE
	)
	var size := text_size + COUNTDOWN_PAD * 2.0
	var top := BonusPainter.label_rect(spec).end.y + 2.0  # under the cup and its label
	return Rect2(Vector2(spec.position.x - size.x * 0.5, top), size)


func _draw_countdowns() -> void:
	if _level == null or _machine == null:
		return
	for i in _level.bonus_pockets.size():
		if _machine.is_open(i) and _level.bonus_pockets[i].role == BonusPocketSpec.Role.ATTACKER:
			_draw_countdown(i)


func _draw_countdown(index: int) -> void:
	var rect := countdown_rect(index)
	var box := StyleBoxFlat.new()
	box.bg_color = Color(0.04, 0.02, 0.08, 0.85)
	box.border_color = Color("ffe27a")
	box.set_border_width_all(1)
	box.set_corner_radius_all(5)
	_countdowns.draw_style_box(box, rect)
	var font := ThemeDB.fallback_font
	var at := (
		rect.position + Vector2(COUNTDOWN_PAD.x, COUNTDOWN_PAD.y + font.get_ascent(COUNTDOWN_SIZE))
	)
	_countdowns.draw_string(
		font,
		at,
		countdown_text(index),
		HORIZONTAL_ALIGNMENT_LEFT,
		-1,
		COUNTDOWN_SIZE,
		Color("ffe27a")
	)
