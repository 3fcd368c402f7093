class_name MazeNote
extends VBoxContainer
## The seed's note under the joystick: a line and a smaller hint, fading in and out over
## two seconds (the seed's `transition: opacity 2s`).

const FADE_SECONDS := 2.0

var _tween: Tween

@onready var _headline: Label = $Headline
@onready var _hint: Label = $Hint


## Shows `headline` and `hint` and fades the note in.
func show_note(headline: String, hint: String) -> void:
	_headline.text = headline
	_hint.text = hint
	_hint.visible = not hint.is_empty()
	_fade_to(1.0)


## Shows `headline` and `hint` at full strength at once (news that cannot wait for the
## fade: a ball lost).
func show_note_now(headline: String, hint: String) -> void:
	show_note(headline, hint)
	if _tween != null:
		_tween.kill()
	modulate.a = 1.0


## Shows `headline` alone, or fades the note out when there is none (after a win).
func show_or_fade(headline: String) -> void:
	if headline.is_empty():
		fade_out()
	else:
		show_note(headline, "")


## Fades the note out (the game started).
func fade_out() -> void:
	_fade_to(0.0)


## The note's text, headline and hint on two lines (for tests).
func text() -> String:
	return "%s\n%s" % [_headline.text, _hint.text]


func _fade_to(alpha: float) -> void:
	if _tween != null:
		_tween.kill()
	_tween = create_tween()
	_tween.tween_property(self, "modulate:a", alpha, FADE_SECONDS * absf(modulate.a - alpha))
