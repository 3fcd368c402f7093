class_name LevelCard
extends Button
## One board in the level select: its thumbnail, name, description and best result. While
## its file loads (off the main thread) the card says so; a board that failed to load shows
## greyed out with its error. A greyed or loading card can take focus (so the message is
## reachable with keyboard and gamepad) but not start. The focused card shows its whole
## description (or error): its thumbnail gives up the height the extra lines need.

const CARD_SIZE := Vector2(300, 400)
const THUMB_HEIGHT := 206.0
## Greyed (a board that cannot be played), but opaque: the backdrop never shows through text.
const GREYED := Color(0.72, 0.72, 0.76, 1.0)
## A maze card's description shows this many lines beside its medal row.
const MAZE_TEXT_LINES := 3

## The board file this card stands for.
var board_path := ""
## False for a board that failed to load or is still loading.
var playable := false
## True while the board's file is still loading.
var loading := false
## True for one of the player's own boards (user://boards/).
var mine := false
## The board shown (null while loading or when it failed to load).
var level: BoardLevel = null
## True when the board is not open yet (maze progression).
var locked := false
## The name of the board whose finish opens this one ("" when open, or none says).
var unlock_after := ""

var _box: VBoxContainer = null
var _thumbnail: BoardThumbnail = null
var _badges: MedalBadges = null
var _long_text: CardLongText = null  # the description or the error: whole while focused


## Shows the card of `path` as "Loading…" until `setup` fills it in.
func show_loading(path: String) -> void:
	_prepare(path)
	loading = true
	playable = false
	disabled = true
	_thumbnail.waiting = true
	_add_label(path.get_file(), &"")
	_add_label("Loading…", &"HintLabel")
	tooltip_text = path


## Fills the card from a load result; `best` is the best-result line ("" for none).
func setup(result: BoardLoadResult, best: String) -> void:
	_prepare(result.path)
	loading = false
	playable = result.ok()
	level = result.level if playable else null
	locked = false
	disabled = not playable
	_thumbnail.level = result.level
	var file_line := "My board: %s" % board_path.get_file() if mine else ""
	if playable:
		var shown := result.level
		_add_label(shown.display_name if not shown.display_name.is_empty() else shown.board_id, &"")
		if not file_line.is_empty():
			_add_label(file_line, &"HintLabel")
		_add_label(best if not best.is_empty() else _no_best_yet(shown), &"HintLabel")
		# a pachinko card has no medal row: its thumbnail gives up a fourth line (trial 6 saw
		# Windmills' text cut at "…and a ×1…")
		var lines := 4 if shown.is_pachinko() else 3
		_long_text = _long(_add_label(shown.description, &"HintLabel", true), lines)
		tooltip_text = shown.description
	else:
		_add_label("⚠ " + board_path.get_file(), &"WarningLabel")
		var reason := result.error.trim_prefix(board_path + ": ")
		_long_text = _long(_add_label("Can't be played: " + reason, &"HintLabel", true, 4), 4)
		tooltip_text = result.error
	modulate = Color.WHITE if playable else GREYED
	_long_text.set_focused(has_focus())


## Maze progression: medals per mode under the title, or a locked card that cannot start
## and says what opens it. Called again after every load, so it replaces an earlier row.
## The medal times shown come from the card's board.
func show_progress(easy: Medals.Medal, hard: Medals.Medal, is_locked: bool, hint: String) -> void:
	if not playable:
		return
	locked = is_locked
	if _badges == null:
		_badges = MedalBadges.new()
		_box.add_child(_badges)
		_box.move_child(_badges, 2)
		# a window that draws the card small grows the medal text: the card grows as much,
		# so the description keeps its lines
		_badges.minimum_size_changed.connect(_fit_to_badges)
		_fit_to_badges()
		# the medal row takes a line's height: the thumbnail gives it up (on every card, so the
		# row lines up), and the description keeps three lines, which hold every shipped maze
		# board's whole (trial 9 read a two-line description part-way through its scroll)
		if _long_text != null:
			_long_text.set_resting_lines(MAZE_TEXT_LINES)
	_badges.show_medals(
		easy,
		hard,
		hint if is_locked else "",
		Medals.times_for(level, false),
		Medals.times_for(level, true),
		not level.holes.is_empty()
	)
	disabled = locked
	_thumbnail.modulate = Color(1, 1, 1, 0.3 if locked else 1.0)
	tooltip_text = hint if locked else level.description


## The card's description (or its error), fitted to the card and its focus; null while it
## loads.
func long_text() -> CardLongText:
	return _long_text


## The medal row, or null when the card has none.
func medal_badges() -> MedalBadges:
	return _badges


## The texts of the card's labels, top to bottom.
func texts() -> PackedStringArray:
	var found := PackedStringArray()
	for label in find_children("*", "Label", true, false):
		found.append((label as Label).text)
	return found


# Empties the card and gives it its thumbnail again.
func _prepare(path: String) -> void:
	board_path = path
	name = board_path.get_file().get_basename().validate_node_name()
	theme_type_variation = &"CardButton"
	custom_minimum_size = CARD_SIZE
	focus_mode = Control.FOCUS_ALL
	if not focus_entered.is_connected(_on_focus_changed):
		focus_entered.connect(_on_focus_changed)
		focus_exited.connect(_on_focus_changed)
	_long_text = null
	set_process(false)
	if _box != null:
		_box.free()  # at once: the card is refilled in place, nothing of the old box may linger
	_badges = null
	_box = VBoxContainer.new()
	_box.set_anchors_and_offsets_preset(Control.PRESET_FULL_RECT, Control.PRESET_MODE_MINSIZE, 14)
	_box.mouse_filter = Control.MOUSE_FILTER_IGNORE
	_box.add_theme_constant_override("separation", 6)
	add_child(_box)
	_thumbnail = BoardThumbnail.new()
	_thumbnail.custom_minimum_size = Vector2(0, THUMB_HEIGHT)
	_thumbnail.mouse_filter = Control.MOUSE_FILTER_IGNORE
	_box.add_child(_thumbnail)


func _fit_to_badges() -> void:
	var grown := _badges.custom_minimum_size.y - MedalBadges.designed_height()
	custom_minimum_size.y = CARD_SIZE.y + maxf(0.0, grown)


func _process(delta: float) -> void:
	if _long_text != null:
		_long_text.advance(delta)


func _on_focus_changed() -> void:
	if _long_text != null:
		_long_text.set_focused(has_focus())
	set_process(has_focus())


func _long(label: Label, resting_lines: int) -> CardLongText:
	return CardLongText.new(label, _thumbnail, THUMB_HEIGHT, resting_lines)


func _add_label(words: String, variation: StringName, wraps := false, lines := 3) -> Label:
	var label := Label.new()
	label.text = words
	label.theme_type_variation = variation
	label.mouse_filter = Control.MOUSE_FILTER_IGNORE
	label.text_overrun_behavior = TextServer.OVERRUN_TRIM_ELLIPSIS
	if wraps:
		label.autowrap_mode = TextServer.AUTOWRAP_WORD
		label.max_lines_visible = lines
		label.size_flags_vertical = Control.SIZE_EXPAND_FILL
	# a long text is cut at the card's edge, never drawn over the next card
	label.clip_text = true
	_box.add_child(label)
	return label


# What a card says before its board has a best: a maze is finished or not; a pachinko game
# always ends, so its record is the best session (the words of the game's own panel).
static func _no_best_yet(shown: BoardLevel) -> String:
	return "Nothing won yet" if shown.kind == BoardLevel.Kind.PACHINKO else "No finish yet"
