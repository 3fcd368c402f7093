class_name JackpotBanner
extends Node2D
## The jackpot's moments in the middle of the board: once the reach stage has shown the
## three alike, a gold flash across the field with "ROUND 1 / 10" growing as the attacker
## opens; each later round announced ("ROUND 3 / 10"); and at the end what the jackpot paid.
## Play goes on underneath: it is drawn over the balls but takes no input.

## Seconds each moment shows.
const JACKPOT_SECONDS := 3.5
const ROUND_SECONDS := 1.6
const SUMMARY_SECONDS := 5.0
## The summary card: its width as a share of the ring's radius, and its colours.
const CARD_WIDTH := 1.3
const CARD := Color(0.07, 0.04, 0.12, 0.94)
## The card's font sizes (board pixels) and the room each of its lines takes.
const CARD_SIZE := 28
const CARD_TITLE_SIZE := 58
const CARD_LINE := 40.0
const CARD_EDGE := Color("ffcf4a")

var _center := Vector2.ZERO
var _radius := 300.0
var _age := 0.0
var _seconds := 0.0
var _title := ""
var _subtitle := ""
var _flash := false
## The summary card's lines under its title (empty: no card, a plain moment).
var _lines := PackedStringArray()


## Shows the jackpot on a board with its ring at `center`, `radius` px: its first round of
## `rounds` opens with it.
## The moment waits `delay` seconds (while the reach stage holds the middle).
## `words`, when given, replace "the attacker is open!" under it.
func show_jackpot(
	center: Vector2, radius: float, rounds := JackpotRounds.ROUNDS, delay := 0.0, words := ""
) -> void:
	var subtitle := words if not words.is_empty() else "the attacker is open!"
	_show(center, radius, "ROUND 1 / %d" % rounds, subtitle, JACKPOT_SECONDS, true)
	_age = -maxf(delay, 0.0)


## Announces a jackpot back to back with the last one (JackpotRounds.announcing): "JACKPOT
## AGAIN!" after `delay` seconds (the reach stage's), until its round 1 opens; `last_paid`
## (-1: unknown) is what the jackpot before it paid.
func show_again(center: Vector2, radius: float, delay: float, last_paid := -1) -> void:
	var subtitle := "another %d rounds: get ready!" % JackpotRounds.ROUNDS
	if last_paid >= 0:
		subtitle = "the last one paid +%d · %d more rounds!" % [last_paid, JackpotRounds.ROUNDS]
	var seconds := maxf(JackpotRounds.AGAIN_SECONDS - delay, 1.0)
	_show(center, radius, "JACKPOT AGAIN!", subtitle, seconds, true)
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


## Shows the jackpot's summary once its last round is over: a card with the rounds played,
## the balls it paid and what this game has paid back in all (`session_paid`), held
## SUMMARY_SECONDS so it can be read while play goes on.
func show_summary(
	center: Vector2, radius: float, rounds_played: int, paid: int, session_paid: int
) -> void:
	var balls := "+1 BALL" if paid == 1 else "+%d BALLS" % paid
	_show(center, radius, balls, "JACKPOT OVER", SUMMARY_SECONDS, false)
	_lines = PackedStringArray(
		[
			"%d %s played" % [rounds_played, "round" if rounds_played == 1 else "rounds"],
			"This game so far: %d balls paid back" % session_paid,
		]
	)


## Shows another moment (the gold pins' prize): `title` large with a gold flash, `subtitle`
## under it, for `seconds`. Its caller waits while a moment is showing: one at a time.
func show_moment(
	center: Vector2, radius: float, title: String, subtitle: String, seconds: float
) -> void:
	_show(center, radius, title, subtitle, seconds, true)


## Takes the moment off the screen at once (the MACHINE CLEARED! card came up over it).
func dismiss() -> void:
	_age = 0.0
	_seconds = 0.0
	_lines = PackedStringArray()
	set_process(false)
	queue_redraw()


## True while a moment is on screen or waiting its turn (a jackpot's waits for the stage).
func is_showing() -> bool:
	return _age < _seconds


## True while a moment is drawn now (not while it waits its turn).
func is_drawn() -> bool:
	return is_showing() and _age >= 0.0


## The words on screen now: title and subtitle, then a summary's lines ("" when nothing
## shows).
func caption() -> String:
	if not is_showing():
		return ""
	var words := PackedStringArray([_title, _subtitle])
	words.append_array(_lines)
	return " ".join(words)


func _show(
	center: Vector2, radius: float, title: String, subtitle: String, seconds: float, flash: bool
) -> void:
	_center = center
	_radius = radius
	_title = title
	_subtitle = subtitle
	_seconds = seconds
	_flash = flash
	_lines = PackedStringArray()
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
	if not _lines.is_empty():
		_draw_card(font, fade)
		return
	var size := int(40 + 30 * minf(t * 5.0, 1.0))
	var at := _center + Vector2(0, _radius * 0.05)
	_centered(font, _title, at, size, Color("ffe14d"), fade)
	if t > 0.15:
		_centered(font, _subtitle, at + Vector2(0.0, 40.0), 26, Color.WHITE, fade)


# The summary: a dark card with a gold edge, "JACKPOT OVER" over the balls it paid, then
# its lines; steady (no growing title) so it reads at a glance.
func _draw_card(font: Font, fade: float) -> void:
	var width := font.get_string_size(_title, HORIZONTAL_ALIGNMENT_LEFT, -1, CARD_TITLE_SIZE).x
	for line in _lines:
		width = maxf(width, font.get_string_size(line, HORIZONTAL_ALIGNMENT_LEFT, -1, CARD_SIZE).x)
	width = minf(maxf(width + 56.0, _radius * CARD_WIDTH), _radius * 1.9)
	var height := 118.0 + CARD_LINE * _lines.size() + 10.0
	var card := Rect2(_center - Vector2(width, height) * 0.5, Vector2(width, height))
	var box := StyleBoxFlat.new()
	box.bg_color = Color(CARD, CARD.a * fade)
	box.border_color = Color(CARD_EDGE, fade)
	box.set_border_width_all(4)
	box.set_corner_radius_all(14)
	draw_style_box(box, card)
	var top := card.position.y
	_centered(font, _subtitle, Vector2(_center.x, top + 40.0), CARD_SIZE, Color.WHITE, fade)
	_centered(font, _title, Vector2(_center.x, top + 98.0), CARD_TITLE_SIZE, Color("ffe14d"), fade)
	for i in _lines.size():
		var at := Vector2(_center.x, top + 98.0 + CARD_LINE * (i + 1))
		_centered(font, _lines[i], at, CARD_SIZE, Color("f3ecff"), fade)


func _centered(font: Font, text: String, at: Vector2, size: int, color: Color, fade: float) -> void:
	var width := font.get_string_size(text, HORIZONTAL_ALIGNMENT_LEFT, -1, size).x
	var pos := at - Vector2(width * 0.5, 0.0)
	draw_string_outline(
		font, pos, text, HORIZONTAL_ALIGNMENT_LEFT, -1, size, 8, Color(0.35, 0.05, 0.0, fade)
	)
	draw_string(font, pos, text, HORIZONTAL_ALIGNMENT_LEFT, -1, size, Color(color, fade))
