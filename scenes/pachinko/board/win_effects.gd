extends Node2D
## Short-lived effects over the board: a rising "+4" and a ring of sparks where a pocket
## paid out, and a puff where a weak shot came back. All in one draw, no node per effect.

const LIFETIME := 1.8
const SPARKS := 12

var _effects: Array[Dictionary] = []


## A payout of `amount` balls at `at` (board coordinates).
func pocket_win(at: Vector2, amount: int) -> void:
	_effects.append({"at": at, "text": "+%d" % amount, "age": 0.0, "color": Color("ffe08a")})
	set_process(true)


## A floating note at `at`, for smaller events (a ball returned to the cup).
func note(at: Vector2, text: String, color: Color) -> void:
	_effects.append({"at": at, "text": text, "age": 0.0, "color": color, "quiet": true})
	set_process(true)


## Effects still showing.
func active_count() -> int:
	return _effects.size()


func _ready() -> void:
	set_process(false)


func _process(delta: float) -> void:
	for effect in _effects:
		effect["age"] = float(effect["age"]) + delta
	_effects = _effects.filter(func(e: Dictionary) -> bool: return float(e["age"]) < LIFETIME)
	queue_redraw()
	if _effects.is_empty():
		set_process(false)


func _draw() -> void:
	var font := ThemeDB.fallback_font
	for effect in _effects:
		var t: float = float(effect["age"]) / LIFETIME
		var at: Vector2 = effect["at"]
		var color: Color = effect["color"]
		# Full strength for most of the life, then a quick fade.
		var fade := clampf((1.0 - t) / 0.35, 0.0, 1.0)
		var quiet := effect.has("quiet")
		if not quiet:
			draw_circle(at, 16.0 + 30.0 * t, Color(1.0, 0.85, 0.35, 0.22 * fade))
			for i in SPARKS:
				var a := TAU * float(i) / SPARKS + t
				var dir := Vector2(cos(a), sin(a))
				var p := at + dir * (8.0 + 46.0 * t)
				draw_line(p, p + dir * 7.0 * fade, Color(color, fade), 2.5, true)
			draw_arc(at, 10.0 + 40.0 * t, 0.0, TAU, 32, Color(1, 1, 1, 0.6 * fade), 2.0, true)
		var size := 16 if quiet else int(30 + 14 * minf(t * 4.0, 1.0))
		var text: String = effect["text"]
		var width := font.get_string_size(text, HORIZONTAL_ALIGNMENT_LEFT, -1, size).x
		var pos := at + Vector2(-width * 0.5, -20.0 - 50.0 * t)
		draw_string_outline(
			font, pos, text, HORIZONTAL_ALIGNMENT_LEFT, -1, size, 5, Color(0.1, 0.02, 0.05, fade)
		)
		draw_string(font, pos, text, HORIZONTAL_ALIGNMENT_LEFT, -1, size, Color(color, fade))
