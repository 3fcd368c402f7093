class_name CardLongText
extends RefCounted
## The long text of a level select card (its description, or why it cannot be played). While
## the card is not focused it keeps to a few lines, ending in "…". Every card's thumbnail
## gives up the height (down to THUMB_MIN_HEIGHT) those lines need, so the cards line up. On
## the focused card a longer text (a description may have 600 characters) reads through: it
## rests on its first lines for START_REST_SECONDS, moves up a line every READ_SECONDS until
## its last line has shown, rests, and starts again from the top. Once moved on it has no
## "…" (trial 9 read "of turns that double back, with... stops part-way.": the label cuts the
## line where the resting text ends, wherever that line now sits). The card keeps its size
## throughout, so nothing around it moves.

const THUMB_MIN_HEIGHT := 56.0
const READ_SECONDS := 1.5
## A text that reads through first rests this long on its first lines (seconds).
const START_REST_SECONDS := 3.0
const END_REST_SECONDS := 2.5

## The label that holds the text.
var label: Label = null

var _thumbnail: Control = null
var _thumb_height := 0.0
var _resting_lines := 3
var _focused := false
var _hidden_lines := 0  # lines that do not fit even with the thumbnail at its least
var _clock := 0.0


## `text_label` shows the text in `resting_lines` lines under `thumbnail` (whose full height
## is `thumb_height`).
func _init(text_label: Label, thumbnail: Control, thumb_height: float, resting_lines: int) -> void:
	label = text_label
	_thumbnail = thumbnail
	_thumb_height = thumb_height
	_resting_lines = resting_lines
	label.resized.connect(fit)


## How many lines show while the card is not focused (a maze card's medal row takes one).
func set_resting_lines(lines: int) -> void:
	_resting_lines = lines
	fit()


## The card took (true) or lost the focus.
func set_focused(focused: bool) -> void:
	_focused = focused
	_clock = 0.0
	label.lines_skipped = 0
	_set_cut_mark(true)
	fit()


## Sizes the thumbnail and the text for the card's focus (again after any resize). The
## thumbnail is as tall on a focused card as on the others, so the row lines up (a play trial
## saw the focused card's name jump 6 px): it gives up what the resting lines need, on every
## card. A focused text longer than those lines reads through them.
func fit() -> void:
	if label.size.y <= 0.0:
		_show_lines(_resting_lines)
		_hidden_lines = 0
		return
	var line_height := _line_height()
	# the text's height with the thumbnail at its full size
	var room := label.size.y - (_thumb_height - _thumbnail.custom_minimum_size.y)
	var shortfall := ceilf(maxf(_resting_lines * line_height - room, 0.0))
	_thumbnail.custom_minimum_size.y = maxf(_thumb_height - shortfall, THUMB_MIN_HEIGHT)
	_show_lines(_resting_lines)
	_hidden_lines = maxi(wrapped_lines() - _resting_lines, 0) if _focused else 0


## Moves a text too long for the focused card on by `delta` seconds of reading.
func advance(delta: float) -> void:
	if not _focused or _hidden_lines == 0:
		return
	_clock += delta
	var steps := 0
	if _clock >= START_REST_SECONDS:
		steps = 1 + floori((_clock - START_REST_SECONDS) / READ_SECONDS)
	if steps > _hidden_lines + ceili(END_REST_SECONDS / READ_SECONDS):
		_clock = 0.0
		steps = 0
	var skipped := mini(steps, _hidden_lines)
	if skipped != label.lines_skipped:
		label.lines_skipped = skipped
		_set_cut_mark(skipped == 0)


## True when every line of the text shows at once.
func shows_whole_text() -> bool:
	return label.lines_skipped == 0 and _hidden_lines == 0 and _visible_lines() >= wrapped_lines()


## True when the text is too long even for the focused card and reads through instead.
func reads_through() -> bool:
	return _focused and _hidden_lines > 0


## The last line of the text is showing (reading through, or the whole text at once).
func shows_last_line() -> bool:
	return label.lines_skipped + _visible_lines() >= wrapped_lines()


## The lines the text wraps into at the label's width (measured with its font: the label's
## own count only catches up when it is drawn).
func wrapped_lines() -> int:
	var font := label.get_theme_font(&"font")
	var font_size := label.get_theme_font_size(&"font_size")
	var width := label.size.x
	var height := (
		font.get_multiline_string_size(label.text, HORIZONTAL_ALIGNMENT_LEFT, width, font_size).y
	)
	return ceili(height / maxf(font.get_height(font_size), 1.0))


func _visible_lines() -> int:
	var by_height := floori((label.size.y + 0.5) / _line_height())
	var limit := label.max_lines_visible
	return mini(by_height, limit) if limit >= 0 else by_height


func _line_height() -> float:
	return maxf(label.get_line_height() + label.get_theme_constant(&"line_spacing"), 1.0)


func _show_lines(count: int) -> void:
	if label.max_lines_visible == count:
		return
	label.max_lines_visible = count
	_set_cut_mark(label.lines_skipped == 0)


# "…" where the text is cut (`shown`), or none. The label cuts its text only when it
# reshapes, which a new line limit alone does not ask for: switching the cut off and on again
# does. The cut falls on the last resting line of the whole text, not of what is shown, so a
# text moved on shows none.
func _set_cut_mark(shown: bool) -> void:
	label.text_overrun_behavior = TextServer.OVERRUN_NO_TRIMMING
	if shown:
		label.text_overrun_behavior = TextServer.OVERRUN_TRIM_ELLIPSIS
