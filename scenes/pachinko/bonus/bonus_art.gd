class_name BonusArt
extends Node2D
## The live bonus pockets over the board: each cup with its lid or wings as the world has
## them, a lamp that flashes when it catches a ball and glows while an attacker is open,
## and an open attacker's seconds and catches left. Reads BonusMachine; never changes it.

## Seconds a catch keeps a lamp lit.
const FLASH_SECONDS := 0.8

var _level: BoardLevel
var _machine: BonusMachine
var _light := PackedFloat32Array()
var _clock := 0.0


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
		if open and spec.role == BonusPocketSpec.Role.ATTACKER:
			_draw_countdown(spec, i)


func _draw_countdown(spec: BonusPocketSpec, index: int) -> void:
	var font := ThemeDB.fallback_font
	var text := (
		"%.0f s · %d left" % [ceilf(_machine.time_left(index)), _machine.catches_left(index)]
	)
	var size := 13
	var width := font.get_string_size(text, HORIZONTAL_ALIGNMENT_LEFT, -1, size).x
	var at := spec.position + Vector2(-width * 0.5, -spec.width * 0.45 - 8.0)
	draw_string_outline(
		font, at, text, HORIZONTAL_ALIGNMENT_LEFT, -1, size, 4, Color(0, 0, 0, 0.85)
	)
	draw_string(font, at, text, HORIZONTAL_ALIGNMENT_LEFT, -1, size, Color("ffe27a"))
