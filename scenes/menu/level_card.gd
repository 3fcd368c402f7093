extends Button
## One board in the level select: its thumbnail, name, description and best result. A board
## that failed to load shows greyed out with its error; it can take focus (so the message is
## reachable with keyboard and gamepad) but not start.

const BoardThumbnail := preload("res://scenes/menu/board_thumbnail.gd")
const MedalBadges := preload("res://scenes/menu/medal_badges.gd")
const CARD_SIZE := Vector2(300, 430)
const THUMB_HEIGHT := 228.0

## The board file this card stands for.
var board_path := ""
## False for a board that failed to load.
var playable := false
## The board shown (null when it failed to load).
var level: BoardLevel
## True when the board is not open yet (maze progression).
var locked := false
var _box: VBoxContainer
var _thumbnail: Control


## Fills the card from a load result; `best` is the best-result line ("" for none).
func setup(result: BoardLoadResult, best: String) -> void:
	board_path = result.path
	playable = result.ok()
	level = result.level
	name = board_path.get_file().get_basename().validate_node_name()
	theme_type_variation = &"CardButton"
	custom_minimum_size = CARD_SIZE
	disabled = not playable
	focus_mode = Control.FOCUS_ALL
	var box := VBoxContainer.new()
	box.set_anchors_and_offsets_preset(Control.PRESET_FULL_RECT, Control.PRESET_MODE_MINSIZE, 14)
	box.mouse_filter = Control.MOUSE_FILTER_IGNORE
	box.add_theme_constant_override("separation", 6)
	add_child(box)
	_box = box
	var thumbnail := BoardThumbnail.new()
	thumbnail.custom_minimum_size = Vector2(0, THUMB_HEIGHT)
	thumbnail.mouse_filter = Control.MOUSE_FILTER_IGNORE
	thumbnail.level = result.level
	box.add_child(thumbnail)
	_thumbnail = thumbnail
	if playable:
		var shown := result.level
		_add_label(
			box, shown.display_name if not shown.display_name.is_empty() else shown.board_id, &""
		)
		_add_label(box, best if not best.is_empty() else "Not played yet", &"HintLabel")
		_add_label(box, shown.description, &"HintLabel", true)
		tooltip_text = shown.description
	else:
		_add_label(box, "⚠ " + board_path.get_file(), &"WarningLabel")
		_add_label(
			box,
			"Can't be played: " + result.error.trim_prefix(board_path + ": "),
			&"HintLabel",
			true,
			4
		)
		tooltip_text = result.error
		modulate = Color(1, 1, 1, 0.7)


## Maze progression: medals per mode under the title, or a locked card that cannot start
## and says what opens it.
func show_progress(easy: Medals.Medal, hard: Medals.Medal, is_locked: bool, hint: String) -> void:
	if not playable:
		return
	locked = is_locked
	var badges := MedalBadges.new()
	badges.show_medals(easy, hard, hint if is_locked else "")
	_box.add_child(badges)
	_box.move_child(badges, 2)
	# the medal row takes a line's height: the description gives one up to fit the card
	var description := _box.get_child(_box.get_child_count() - 1) as Label
	if description != null:
		description.max_lines_visible = 2
	if locked:
		disabled = true
		_thumbnail.modulate = Color(1, 1, 1, 0.3)
		tooltip_text = hint


func _add_label(
	box: VBoxContainer, words: String, variation: StringName, wraps := false, lines := 3
) -> void:
	var label := Label.new()
	label.text = words
	label.theme_type_variation = variation
	label.mouse_filter = Control.MOUSE_FILTER_IGNORE
	label.text_overrun_behavior = TextServer.OVERRUN_TRIM_ELLIPSIS
	if wraps:
		label.autowrap_mode = TextServer.AUTOWRAP_WORD_SMART
		label.max_lines_visible = lines
		label.size_flags_vertical = Control.SIZE_EXPAND_FILL
	else:
		label.clip_text = true
	box.add_child(label)
