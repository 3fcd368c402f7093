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
## what it won for the board's best, so the card says it once for all of them.
const SESSION_KEPT := "A new game (%s) ends this one; what it won still counts for your best."

## The keys that start a game from the card (PachinkoGame's start keys).
const START_ACTIONS: Array[StringName] = [&"game_start", &"launch_charge", &"launch_handle"]

## What this board's pieces do, under the words (only at the start).
var _legend := PieceLegend.new()
## Seconds since the card last came up.
var _shown_seconds := 0.0
var _nudge: Tween
# The start keys already held as the card came up (the stream key held as the last ball
# came down): ignored until let go, so a held key never skips the game's summary.
var _held_over: Array[StringName] = []

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


## True when `event` comes from a start key that was already held as the card came up: the
## card ignores it (a play trial's held stream key skipped the game-over summary) until the
## key is let go, and its release is swallowed too.
func ignores_held(event: InputEvent) -> bool:
	for action in _held_over:
		if event.is_action(action):
			if event.is_released():
				_held_over.erase(action)
			return true
	return false


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


## The first screen: how to play `level`, short enough to read in a few seconds (a play
## trial spent 20 s on the long one before its first shot): how to shoot in one line, the
## cup, the board's pieces.
func show_start(level: BoardLevel) -> void:
	_title.text = "Pachinko · %s" % level.display_name
	_body.text = (
		"\n"
		. join(
			PackedStringArray(
				[
					how_to_shoot(),
					(
						(
							"You have [b]%d balls[/b]. The stronger the shot, the farther round the"
							+ " top it travels. On the power bar, green marks the powers that have"
							+ " been paying; the gold arrow marks your last shot."
						)
						% level.cup_start_balls
					),
					SESSION_KEPT % KeyNames.of(&"game_restart", "the restart key"),
				]
			)
		)
	)
	if PachinkoGoals.tray_target(level) > 0:
		_body.text += "\n[b]Goal:[/b] %s to clear this machine." % PachinkoGoals.words(level)
	_body.text += "\n" + GoldPinsText.card_line(level)
	_legend.show_pieces(level)
	_legend.visible = true
	_show_play("Play", "or press %s" % _start_keys())


## How to shoot, in one line of BBCode (the start card's first line): a shot and a stream.
static func how_to_shoot() -> String:
	return "%s %s" % [how_to_shoot_once(), how_to_stream()]


## How to fire one shot, in BBCode.
static func how_to_shoot_once() -> String:
	return (
		"[b]Shoot:[/b] hold [b]%s[/b] and let go (or drag the red grip up)."
		% PlainMarkup.escape(KeyNames.of(&"launch_charge", "the charge key"))
	)


## How to stream balls, in BBCode.
static func how_to_stream() -> String:
	return (
		"[b]Stream:[/b] hold [b]%s[/b]."
		% PlainMarkup.escape(KeyNames.of(&"launch_handle", "the handle key"))
	)


## True for a left click (on the card's screen it only points at the Play button).
static func is_click(event: InputEvent) -> bool:
	var button := event as InputEventMouseButton
	return button != null and button.pressed and button.button_index == MOUSE_BUTTON_LEFT


## True for any of the keys a player reaches for first (START_ACTIONS: start, charge or the
## handle), which start the game from the card; never a mouse button.
static func is_start_key(event: InputEvent) -> bool:
	if event is InputEventMouseButton:
		return false
	for action in START_ACTIONS:
		if event.is_action_pressed(action):
			return true
	return false


## The card itself (the panel is the board's whole area), for tests of its fit.
func card() -> Control:
	return _card


## The game-over screen with the last game's numbers; `new_best` when it beat the record.
func show_game_over(level: BoardLevel, summary: Dictionary, best: int, new_best: bool) -> void:
	_title.text = "New best!" if new_best else "Game over"
	var shots: int = summary.get("game_shots", 0)
	var paid: int = summary.get("game_payouts", 0)
	var hits: int = summary.get("game_hits", 0)
	var won: int = summary.get("game_won", 0)
	var lines := PackedStringArray(
		[
			(
				"[b]%d[/b] shots, [b]%d[/b] pocket hits, [b]%d[/b] balls paid back."
				% [shots, hits, paid]
			),
			_result_line(won, level.cup_start_balls),
		]
	)
	if best > 0:
		var board_name := PlainMarkup.escape(level.display_name)
		lines.append("Best game on %s: [b]+%d[/b] balls." % [board_name, best])
	lines.append("")
	lines.append("Another %d balls are waiting." % level.cup_start_balls)
	_body.text = "\n".join(lines)
	_legend.visible = false
	_show_play("Play again", "or press %s" % _start_keys())


# This game's result: `won` balls over its `start` (trial 8: the card said the game's
# highest point, which the game had lost again).
static func _result_line(won: int, start: int) -> String:
	if won > 0:
		return "You ended [b]%d[/b] balls up." % won
	if won == -start:
		return "The tray ran dry: the %d balls you started with are gone." % start
	return "You ended [b]%d[/b] balls down." % -won if won < 0 else "You ended even."


## A board that cannot be played: says what went wrong and how to get back.
func show_problem(problem: String) -> void:
	_title.text = "This board could not be loaded"
	_legend.visible = false
	_body.text = PlainMarkup.escape(problem)
	_footer.text = "Press Esc for the menu"
	_play.visible = false
	visible = true


# The keys that press Play, as the footer names them.
static func _start_keys() -> String:
	return (
		"%s or %s"
		% [
			KeyNames.of(&"game_start", "the start key"),
			KeyNames.of(&"launch_charge", "the charge key")
		]
	)


# Up with its Play button reading `words` over `footer`; the read time starts now.
func _show_play(words: String, footer: String) -> void:
	_play.text = words
	_play.visible = true
	_footer.text = footer
	_shown_seconds = 0.0
	visible = true
	_held_over.clear()
	for action in START_ACTIONS:
		if Input.is_action_pressed(action):
			_held_over.append(action)


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
	# never bigger than the panel: a card too tall for it (Fever's at 1280 × 720) is drawn
	# smaller rather than cut off
	_card.scale = Vector2.ONE * minf(maxf(wanted, 1.0), room)
