class_name MazeWinPanel
extends CenterContainer
## The card that shows over the board when a maze is won: the medal earned drawn large, the
## time, the medal's line (or how far it was from the next), the change against the best
## time, and Next board / Retry / Menu; or, when a ball is lost into a hole, that the run
## can't be won, with Retry / Menu. The buttons take keyboard and gamepad focus (the
## first shown one gets it).

## The player chose the next board.
signal next_board_chosen
## The player chose to play this board again.
signal retry_chosen
## The player chose the level select.
signal menu_chosen

const INK := Color(0.129, 0.004, 0.141)
## The card's colour.
const CARD := Color(0.99, 0.97, 0.94, 0.96)
## The fill of the card's buttons (all alike; the focused one only gains the ring).
const BUTTON_FILL := Color(0.93, 0.87, 0.76)

## How long after the card appears it ignores the arrow and accept keys (ms)...
const HELD_KEYS_IGNORED_MSEC := 600
## ...and for at least this many drawn frames: on a slow machine (trial 9: 3-37 FPS) a tap
## meant for the last ball lands after 600 ms with the card hardly on the screen, and two of
## them walked the first card's focus from Next board to Menu.
const HELD_KEYS_IGNORED_FRAMES := 6
## The menu keys a key held over from play can press: the arrows that tilted the board, and
## accept.
const MENU_ACTIONS: Array[StringName] = [
	&"ui_left", &"ui_right", &"ui_up", &"ui_down", &"ui_accept"
]

# When the card was last shown (Time.get_ticks_msec).
var _shown_at_msec := -1000000
# Frames drawn since the card was last shown.
var _frames_shown := 0
# The menu actions held down as the card appeared: ignored until let go (their repeats go on
# for as long as the key is held, well past the card's first moments).
var _held_over: Array[StringName] = []
var _disc := MazeMedalDisc.new()
var _headline := Label.new()
var _time := Label.new()
var _medal := Label.new()
var _best := Label.new()
var _next := Button.new()
var _retry := Button.new()
var _menu := Button.new()
var _text: MazeSideText  # keeps the card's text readable where the window draws it small


func _init() -> void:
	name = "WinPanel"
	set_anchors_preset(Control.PRESET_FULL_RECT)
	mouse_filter = Control.MOUSE_FILTER_IGNORE
	var panel := PanelContainer.new()
	var style := StyleBoxFlat.new()
	style.bg_color = CARD
	style.border_color = Color(INK, 0.35)
	style.set_border_width_all(2)
	style.set_corner_radius_all(14)
	style.set_content_margin_all(26)
	style.shadow_color = Color(0, 0, 0, 0.25)
	style.shadow_size = 10
	panel.add_theme_stylebox_override("panel", style)
	add_child(panel)
	var box := VBoxContainer.new()
	box.add_theme_constant_override("separation", 10)
	panel.add_child(box)
	_style_label(_headline, 30, 1.0)
	_headline.text = "You did it!"
	_style_label(_time, 24, 1.0)
	_style_label(_medal, 20, 1.0)
	_style_label(_best, 17, 0.8)
	_disc.size_flags_horizontal = Control.SIZE_SHRINK_CENTER
	box.add_child(_disc)
	for label: Label in [_headline, _time, _medal, _best]:
		box.add_child(label)
	var row := HBoxContainer.new()
	row.alignment = BoxContainer.ALIGNMENT_CENTER
	row.add_theme_constant_override("separation", 12)
	box.add_child(row)
	_next.text = "Next board"
	_retry.text = "Retry"
	_menu.text = "Menu"
	for button: Button in [_next, _retry, _menu]:
		button.custom_minimum_size = Vector2(130, 44)
		button.focus_mode = Control.FOCUS_ALL
		MazeFocusRing.apply(button)
		_style_button(button)
		row.add_child(button)
	_next.pressed.connect(func() -> void: next_board_chosen.emit())
	_retry.pressed.connect(func() -> void: retry_chosen.emit())
	_menu.pressed.connect(func() -> void: menu_chosen.emit())
	_text = MazeSideText.new(panel)
	resized.connect(_fit_text)
	hide()


## Shows `summary`; `has_next` shows the Next board button (false after the last board or
## on a board of the player's own). The first button shown takes the focus.
func present(summary: MazeWinSummary, hard: bool, has_next: bool) -> void:
	_time.text = "%s  ·  %s" % [MazeWinSummary.clock(summary.seconds), "hard" if hard else "easy"]
	var medal_text := summary.medal_line()
	_medal.text = medal_text
	_medal.visible = not medal_text.is_empty()
	var colour: Color = MedalBadges.COLORS.get(summary.medal, INK)
	_medal.add_theme_color_override("font_color", colour.darkened(0.55))
	_best.text = summary.best_line()
	_headline.text = summary.headline()
	_disc.medal = summary.medal
	_next.visible = has_next
	_appear()
	(_next if has_next else _retry).grab_focus.call_deferred()


## Shows the card of a run lost into a hole: what happened, that it can't be won any
## more (said once, plainly: no count of balls left), and Retry (focused) and Menu.
func present_loss() -> void:
	_headline.text = "Ball lost"
	_time.text = "A ball fell into a black hole."
	_medal.text = "This run can't be won: retry!"
	_medal.visible = true
	_medal.add_theme_color_override("font_color", INK)
	_best.text = ""
	_disc.medal = Medals.Medal.NONE
	_next.visible = false
	_appear()
	_retry.grab_focus.call_deferred()


# Shows the card and notes which menu keys are held over from play.
func _appear() -> void:
	show()
	_shown_at_msec = Time.get_ticks_msec()
	_frames_shown = 0
	_held_over.clear()
	for action in MENU_ACTIONS:
		if Input.is_action_pressed(action):
			_held_over.append(action)


func _input(event: InputEvent) -> void:
	# the arrow keys that tilted the board are Godot's menu keys too: a key still held as the
	# last ball rolls in would walk the focus from Next board to Menu with its repeats (a play
	# trial pressed Enter on Menu that way), so the card ignores a key held over from play
	# until it is let go, and any menu key in its first moments
	if not visible:
		return
	for action in MENU_ACTIONS:
		if not event.is_action(action):
			continue
		if action in _held_over:
			if event.is_released():
				_held_over.erase(action)
			get_viewport().set_input_as_handled()
			return
		if _settling():
			get_viewport().set_input_as_handled()
			return


func _process(_delta: float) -> void:
	if visible:
		_frames_shown += 1


# True in the card's first moments, when a menu key is still one meant for the board.
func _settling() -> bool:
	var young := Time.get_ticks_msec() - _shown_at_msec <= HELD_KEYS_IGNORED_MSEC
	return young or _frames_shown < HELD_KEYS_IGNORED_FRAMES


## The texts shown, top to bottom (for tests).
func texts() -> PackedStringArray:
	return PackedStringArray([_headline.text, _time.text, _medal.text, _best.text])


## The medal drawn large (hidden when the run earned none).
func medal_disc() -> Control:
	return _disc


# One look for every card button (the default theme's grey made Retry and Menu look
# disabled next to the focused Next board): ink text on a light fill, darker when hovered.
static func _style_button(button: Button) -> void:
	for state: String in ["normal", "hover", "pressed", "disabled"]:
		var box := StyleBoxFlat.new()
		box.bg_color = BUTTON_FILL.darkened(0.12 if state == "hover" else 0.0)
		box.border_color = INK
		box.set_border_width_all(2)
		box.set_corner_radius_all(MazeFocusRing.CORNER)
		button.add_theme_stylebox_override(state, box)
	for colour: String in [
		"font_color", "font_hover_color", "font_pressed_color", "font_focus_color"
	]:
		button.add_theme_color_override(colour, INK)


## The buttons in order: Next board, Retry, Menu.
func buttons() -> Array[Button]:
	return [_next, _retry, _menu]


func _style_label(label: Label, font_size: int, alpha: float) -> void:
	label.horizontal_alignment = HORIZONTAL_ALIGNMENT_CENTER
	label.add_theme_font_size_override("font_size", font_size)
	label.add_theme_color_override("font_color", Color(INK, alpha))


## How much the card's text is grown for the screen (1: its design sizes).
func text_factor() -> float:
	return _text.factor


# Grows the card's text so its smallest is ReadableText.MIN_SCREEN_PX on the screen (the
# card sits over the board, which leaves it room at any window size).
func _fit_text() -> void:
	if is_inside_tree():
		_text.apply(get_viewport().get_final_transform().get_scale().y)
