class_name WinEffects
extends Node2D
## Short-lived effects over the board: a rising "+4" and a ring of sparks where a pocket
## paid out, and a puff where a weak shot came back. All in one draw, no node per effect.

const LIFETIME := 1.8
const SPARKS := 12

var _effects: Array[Effect] = []


## A payout of `amount` balls at `at` (board coordinates).
func pocket_win(at: Vector2, amount: int) -> void:
	_effects.append(Effect.new(at, "+%d" % amount, Color("ffe08a"), false))
	set_process(true)


## A floating note at `at`, for smaller events (a ball returned to the cup).
func note(at: Vector2, text: String, color: Color) -> void:
	_effects.append(Effect.new(at, text, color, true))
	set_process(true)


## Effects still showing.
func active_count() -> int:
	return _effects.size()


func _ready() -> void:
	set_process(false)


func _process(delta: float) -> void:
	for effect in _effects:
		effect.age += delta
	_effects = _effects.filter(func(e: Effect) -> bool: return e.age < LIFETIME)
	queue_redraw()
	if _effects.is_empty():
		set_process(false)


func _draw() -> void:
	var font := ThemeDB.fallback_font
	for effect in _effects:
		var t := effect.age / LIFETIME
		var at := effect.at
		var color := effect.color
		# Full strength for most of the life, then a quick fade.
		var fade := clampf((1.0 - t) / 0.35, 0.0, 1.0)
		var quiet := effect.quiet
		if not quiet:
			draw_circle(at, 16.0 + 30.0 * t, Color(1.0, 0.85, 0.35, 0.22 * fade))
			for i in SPARKS:
				var a := TAU * float(i) / SPARKS + t
				var dir := Vector2(cos(a), sin(a))
				var p := at + dir * (8.0 + 46.0 * t)
				draw_line(p, p + dir * 7.0 * fade, Color(color, fade), 2.5, true)
			draw_arc(at, 10.0 + 40.0 * t, 0.0, TAU, 32, Color(1, 1, 1, 0.6 * fade), 2.0, true)
		var size := 16 if quiet else int(30 + 14 * minf(t * 4.0, 1.0))
		var text := effect.text
		var width := font.get_string_size(text, HORIZONTAL_ALIGNMENT_LEFT, -1, size).x
		var pos := at + Vector2(-width * 0.5, -20.0 - 50.0 * t)
		draw_string_outline(
			font, pos, text, HORIZONTAL_ALIGNMENT_LEFT, -1, size, 5, Color(0.1, 0.02, 0.05, fade)
		)
		draw_string(font, pos, text, HORIZONTAL_ALIGNMENT_LEFT, -1, size, Color(color, fade))


## One showing effect; `quiet` ones are small notes with no sparks.
class Effect:
	var at: Vector2
	var text: String
	var color: Color
	var quiet: bool
	var age := 0.0

	func _init(where: Vector2, words: String, tint: Color, is_quiet: bool) -> void:
		at = where
		text = words
		color = tint
		quiet = is_quiet
