extends Node2D
## The jackpot's moments in the middle of the board: once the reach stage has shown the
## three alike, a gold flash across the field with "ROUND 1 / 10" growing as the attacker
## opens; each later round announced ("ROUND 3 / 10"); and at the end what the jackpot paid.
## Play goes on underneath: it is drawn over the balls but takes no input.

## Seconds each moment shows.
const JACKPOT_SECONDS := 3.5
const ROUND_SECONDS := 1.6
const TOTAL_SECONDS := 3.0

var _center := Vector2.ZERO
var _radius := 300.0
var _age := 0.0
var _seconds := 0.0
var _title := ""
var _subtitle := ""
var _flash := false


## Shows the jackpot on a board with its ring at `center`, `radius` px: its first round of
## `rounds` opens with it.
## The moment waits `delay` seconds (while the reach stage holds the middle).
func show_jackpot(
	center: Vector2, radius: float, rounds := JackpotRounds.ROUNDS, delay := 0.0
) -> void:
	_show(center, radius, "ROUND 1 / %d" % rounds, "the attacker is open!", JACKPOT_SECONDS, true)
	_age = -maxf(delay, 0.0)


## Announces round `round_number` of `rounds`.
func show_round(center: Vector2, radius: float, round_number: int, rounds: int) -> void:
	_show(
		center,
		radius,
		"ROUND %d / %d" % [round_number, rounds],
		"feed the attacker!",
		ROUND_SECONDS,
		false
	)


## Shows what the jackpot paid once its last round is over.
func show_total(center: Vector2, radius: float, paid: int) -> void:
	var balls := "1 BALL" if paid == 1 else "%d BALLS" % paid
	_show(center, radius, balls, "the jackpot paid", TOTAL_SECONDS, false)


## True while a moment is on screen.
func is_showing() -> bool:
	return _age < _seconds


## The words on screen now: title and subtitle ("" when nothing shows).
func caption() -> String:
	return "%s %s" % [_title, _subtitle] if is_showing() else ""


func _show(
	center: Vector2, radius: float, title: String, subtitle: String, seconds: float, flash: bool
) -> void:
	_center = center
	_radius = radius
	_title = title
	_subtitle = subtitle
	_seconds = seconds
	_flash = flash
	_age = 0.0
	set_process(true)
	queue_redraw()


func _ready() -> void:
	set_process(false)


func _process(delta: float) -> void:
	_age += delta
	queue_redraw()
	if not is_showing():
		set_process(false)


func _draw() -> void:
	if not is_showing() or _age < 0.0:
		return
	var t := _age / _seconds
	if _flash:
		var flash := (
			maxf(0.0, 1.0 - t * 4.0) * 0.45 + 0.12 * (0.5 + 0.5 * sin(_age * 20.0)) * (1.0 - t)
		)
		draw_circle(_center, _radius, Color(1.0, 0.82, 0.3, flash))
	var fade := clampf((1.0 - t) / 0.3, 0.0, 1.0) * clampf(_age / 0.12, 0.0, 1.0)
	var font := ThemeDB.fallback_font
	var size := int(40 + 30 * minf(t * 5.0, 1.0))
	var at := _center + Vector2(0, _radius * 0.05)
	_centered(font, _title, at, size, Color("ffe14d"), fade)
	if t > 0.15:
		_centered(font, _subtitle, at + Vector2(0.0, 40.0), 26, Color.WHITE, fade)


func _centered(font: Font, text: String, at: Vector2, size: int, color: Color, fade: float) -> void:
	var width := font.get_string_size(text, HORIZONTAL_ALIGNMENT_LEFT, -1, size).x
	var pos := at - Vector2(width * 0.5, 0.0)
	draw_string_outline(
		font, pos, text, HORIZONTAL_ALIGNMENT_LEFT, -1, size, 8, Color(0.35, 0.05, 0.0, fade)
	)
	draw_string(font, pos, text, HORIZONTAL_ALIGNMENT_LEFT, -1, size, Color(color, fade))
