extends Node2D
## The jackpot moment over the board: a gold flash across the field and "JACKPOT!" growing
## in the middle, then "ATTACKER OPEN" while it fades. Play goes on underneath: it is drawn
## over the balls but takes no input.

const SECONDS := 3.5

var _center := Vector2.ZERO
var _radius := 300.0
var _age := SECONDS


## Shows the moment on a board with its ring at `center`, `radius` px.
func show_jackpot(center: Vector2, radius: float) -> void:
	_center = center
	_radius = radius
	_age = 0.0
	set_process(true)


## True while the moment is on screen.
func is_showing() -> bool:
	return _age < SECONDS


func _ready() -> void:
	set_process(false)


func _process(delta: float) -> void:
	_age += delta
	queue_redraw()
	if not is_showing():
		set_process(false)


func _draw() -> void:
	if not is_showing():
		return
	var t := _age / SECONDS
	var flash := maxf(0.0, 1.0 - t * 4.0) * 0.45 + 0.12 * (0.5 + 0.5 * sin(_age * 20.0)) * (1.0 - t)
	draw_circle(_center, _radius, Color(1.0, 0.82, 0.3, flash))
	var fade := clampf((1.0 - t) / 0.3, 0.0, 1.0)
	var font := ThemeDB.fallback_font
	var size := int(40 + 30 * minf(t * 5.0, 1.0))
	_centered(font, "JACKPOT!", _center + Vector2(0, -_radius * 0.12), size, Color("ffe14d"), fade)
	if t > 0.25:
		_centered(
			font,
			"ATTACKER OPEN",
			_center + Vector2(0, -_radius * 0.12 + 40.0),
			22,
			Color.WHITE,
			fade
		)


func _centered(font: Font, text: String, at: Vector2, size: int, color: Color, fade: float) -> void:
	var width := font.get_string_size(text, HORIZONTAL_ALIGNMENT_LEFT, -1, size).x
	var pos := at - Vector2(width * 0.5, 0.0)
	draw_string_outline(
		font, pos, text, HORIZONTAL_ALIGNMENT_LEFT, -1, size, 8, Color(0.35, 0.05, 0.0, fade)
	)
	draw_string(font, pos, text, HORIZONTAL_ALIGNMENT_LEFT, -1, size, Color(color, fade))
