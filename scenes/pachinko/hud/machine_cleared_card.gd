class_name MachineClearedCard
extends PanelContainer
## The win moment: the tray reached the machine's goal (PachinkoGoals). A large card over the
## board with the goal, the balls won and three ways on: Next machine, Keep playing (the game
## goes on: the card goes) and Other boards (the board chooser, as the pause menu's button of
## that name: trial 8 read "Menu" and expected the main menu). The game acts on its signals.

## The player chose the next machine in the list.
signal next_requested
## The player chose the board list.
signal menu_requested

const TITLE_SIZE := 44
## The menus' and pause menu's look, so the buttons are the game's, not Godot's flat grey.
const THEME := preload("res://scenes/menu/ui_theme.tres")
const LINE_SIZE := 20
## The board chooser's button, in the pause menu's words.
const OTHER_BOARDS := "Other boards"

var _title := Label.new()
var _line := Label.new()
var _next := Button.new()
var _keep := Button.new()
var _menu := Button.new()


func _init() -> void:
	visible = false
	theme = THEME
	var style := StyleBoxFlat.new()
	style.bg_color = Color(0.07, 0.04, 0.13, 0.94)
	style.border_color = Color("ffd84a")
	style.set_border_width_all(4)
	style.set_corner_radius_all(16)
	style.set_content_margin_all(28.0)
	add_theme_stylebox_override(&"panel", style)
	var box := VBoxContainer.new()
	box.add_theme_constant_override(&"separation", 14)
	add_child(box)
	_title.text = "MACHINE CLEARED!"
	_title.horizontal_alignment = HORIZONTAL_ALIGNMENT_CENTER
	_title.add_theme_font_size_override(&"font_size", TITLE_SIZE)
	_title.add_theme_color_override(&"font_color", Color("ffd84a"))
	box.add_child(_title)
	_line.horizontal_alignment = HORIZONTAL_ALIGNMENT_CENTER
	_line.add_theme_font_size_override(&"font_size", LINE_SIZE)
	box.add_child(_line)
	var row := HBoxContainer.new()
	row.alignment = BoxContainer.ALIGNMENT_CENTER
	row.add_theme_constant_override(&"separation", 12)
	box.add_child(row)
	for pair: Array in [[_next, "Next machine"], [_keep, "Keep playing"], [_menu, OTHER_BOARDS]]:
		var button: Button = pair[0]
		button.text = pair[1]
		button.add_theme_font_size_override(&"font_size", LINE_SIZE)
		row.add_child(button)
	_next.pressed.connect(func() -> void: next_requested.emit())
	_keep.pressed.connect(dismiss)
	_menu.pressed.connect(func() -> void: menu_requested.emit())


## Shows the win on `level`: its goal reached with `won` balls won; centred on `area`. A
## clear that waited for a jackpot to end says what it paid (`jackpot_paid`, -1: none), as
## the card takes the place of the jackpot's own summary.
func show_cleared(level: BoardLevel, won: int, area: Rect2, jackpot_paid := -1) -> void:
	_line.text = (
		"Tray filled to %d balls!\nYou won %d balls on %s."
		% [PachinkoGoals.tray_target(level), won, level.display_name]
	)
	if jackpot_paid >= 0:
		_line.text += (
			"\nThe jackpot paid %d ball%s." % [jackpot_paid, "" if jackpot_paid == 1 else "s"]
		)
	visible = true
	size = get_combined_minimum_size()
	position = area.get_center() - size * 0.5
	_keep.grab_focus.call_deferred()


## Takes the card away (Keep playing).
func dismiss() -> void:
	visible = false


## Next machine, Keep playing and Other boards, in that order.
func buttons() -> Array[Button]:
	return [_next, _keep, _menu]


## The card's words, for tests.
func text() -> String:
	return "%s %s" % [_title.text, _line.text]
