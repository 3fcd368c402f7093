class_name InstructionsPanel
extends Control
## The instructions panel: up before the first game and again at game over. It goes away
## only when the player means it to: its own Play button or the start key, and only once it
## has been up READ_SECONDS (a click anywhere else, or one still queued from the click that
## chose the board, leaves it up and points at the button). The game scene starts the game
## on `play_requested`; this panel only shows the words. The body is BBCode for the bold
## words: anything in it that came from a file (the board's name, a refusal quoting a
## field) goes through PlainMarkup.escape, the title and footer are plain labels.

## The player asked to play: the Play button, after the card had been up READ_SECONDS.
signal play_requested

## The card's smallest font size (the legend's) in the design: the card is scaled up until
## it reads (ReadableText), while the panel has room.
const SMALLEST_FONT := 14.0
## The share of the panel the scaled card may cover at most, each way.
const MAX_COVER := 0.94
## Seconds the card is up before anything takes it away: a click queued while the board
## loaded, or a double click on the level select, lands before this and is not a choice.
const READ_SECONDS := 0.5
## What ending a game early does (R, the pause menu's Restart, Other boards): all three keep
## what it paid back for the board's best, so the card says it once for all of them.
const SESSION_KEPT := (
	"A new game (%s) or other boards ends this one early; what it paid back still counts"
	+ " for your best."
)

## What this board's pieces do, under the words (only at the start).
var _legend := PieceLegend.new()
## Seconds since the card last came up.
var _shown_seconds := 0.0
var _nudge: Tween

@onready var _title: Label = $Card/Margin/Box/Title
@onready var _body: RichTextLabel = $Card/Margin/Box/Body
@onready var _footer: Label = $Card/Margin/Box/Footer
@onready var _play: Button = $Card/Margin/Box/Play
@onready var _card: Control = $Card


## The legend of the machine's pieces on the start card.
func legend() -> Control:
	return _legend


func _ready() -> void:
	_play.pressed.connect(_on_play_pressed)
	var box := $Card/Margin/Box
	box.add_child(_legend)
	box.move_child(_legend, _body.get_index() + 1)
	resized.connect(_fit_card)
	_card.resized.connect(_fit_card)


func _process(delta: float) -> void:
	_shown_seconds += delta


## True when a start from the player counts: the card is up and has been for READ_SECONDS.
func accepts_start() -> bool:
	return visible and _play.visible and _shown_seconds >= READ_SECONDS


## Points the player at the Play button (they clicked elsewhere on the card's screen).
func nudge() -> void:
	if not visible or not _play.visible or not is_inside_tree():
		return
	if _nudge != null:
		_nudge.kill()
	_play.pivot_offset = _play.size * 0.5
	_nudge = create_tween()
	_nudge.tween_property(_play, "scale", Vector2.ONE * 1.15, 0.08)
	_nudge.tween_property(_play, "scale", Vector2.ONE, 0.18)


## How much the card is scaled up for the screen (1: drawn at its design size).
func card_scale() -> float:
	return _card.scale.x


## The first screen: how to play `level`.
func show_start(level: BoardLevel) -> void:
	_title.text = "Pachinko · %s" % level.display_name
	_body.text = (
		"\n"
		. join(
			PackedStringArray(
				[
					"You get [b]%d balls[/b] in your cup." % level.cup_start_balls,
					(
						"[b]One shot:[/b] press the red grip and drag up to draw the flipper back (the"
						+ (
							" red bar shows the power), or hold [b]%s[/b]; let go to fire."
							% KeyNames.of(&"launch_charge", "the charge key")
						)
					),
					(
						(
							"[b]A stream:[/b] hold the [b]handle dial[/b], [b]%s[/b] or the right"
							+ " trigger and balls fly out at its strength, 100 a minute. Turn it with"
							+ " [b]%s[/b] / [b]%s[/b], the wheel or a drag on the dial."
						)
						% [
							KeyNames.of(&"launch_handle", "the handle key"),
							KeyNames.of(&"handle_weaker", "?"),
							KeyNames.of(&"handle_stronger", "?"),
						]
					),
					(
						"[b]Power aims:[/b] the weakest shot drops in beside the rail on the right; the"
						+ " stronger, the farther left; full power rides over the top to the far side."
						+ " While you aim, dots show the ball's flight to the first pin it meets, and"
						+ " a gold mark on the power bar keeps your last shot."
					),
					"The game ends when the cup is empty and every ball has come down.",
					SESSION_KEPT % KeyNames.of(&"game_restart", "the restart key"),
				]
			)
		)
	)
	_legend.show_pieces(level)
	_legend.visible = true
	_show_play("Play", "or press %s" % KeyNames.of(&"game_start", "the start key"))


## The game-over screen with the last game's numbers; `new_best` when it beat the record.
func show_game_over(level: BoardLevel, summary: Dictionary, best: int, new_best: bool) -> void:
	_title.text = "New best!" if new_best else "Game over"
	var shots: int = summary.get("game_shots", 0)
	var paid: int = summary.get("game_payouts", 0)
	var hits: int = summary.get("game_hits", 0)
	var lines := PackedStringArray(
		[
			(
				"[b]%d[/b] shots, [b]%d[/b] pocket hits, [b]%d[/b] balls paid back."
				% [shots, hits, paid]
			),
		]
	)
	if best > 0:
		var board_name := PlainMarkup.escape(level.display_name)
		lines.append("Best on %s: [b]%d[/b] balls paid back." % [board_name, best])
	lines.append("")
	lines.append("Another %d balls are waiting." % level.cup_start_balls)
	_body.text = "\n".join(lines)
	_legend.visible = false
	_show_play("Play again", "or press %s" % KeyNames.of(&"game_start", "the start key"))


## A board that cannot be played: says what went wrong and how to get back.
func show_problem(problem: String) -> void:
	_title.text = "This board could not be loaded"
	_legend.visible = false
	_body.text = PlainMarkup.escape(problem)
	_footer.text = "Press Esc for the menu"
	_play.visible = false
	visible = true


# Up with its Play button reading `words` over `footer`; the read time starts now.
func _show_play(words: String, footer: String) -> void:
	_play.text = words
	_play.visible = true
	_footer.text = footer
	_shown_seconds = 0.0
	visible = true


func _on_play_pressed() -> void:
	if accepts_start():
		play_requested.emit()


# Scales the card about its centre so its smallest text reads (ReadableText) on the
# screen, as far as the panel has room for it.
func _fit_card() -> void:
	if not is_inside_tree() or _card.size.x <= 0.0 or _card.size.y <= 0.0:
		return
	var wanted := ReadableText.growth_at(SMALLEST_FONT, ReadableText.screen_scale_of(self))
	var room := minf(size.x * MAX_COVER / _card.size.x, size.y * MAX_COVER / _card.size.y)
	_card.pivot_offset = _card.size * 0.5
	_card.scale = Vector2.ONE * clampf(wanted, 1.0, maxf(room, 1.0))
