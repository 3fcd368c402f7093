class_name MazeSideText
extends RefCounted
## Keeps a maze panel's text readable on the screen (the side panel's portrait band, the win
## card). The project draws a 1280 × 720 design stretched to the window (canvas_items), so a
## portrait phone or a small window draws it smaller: then every label and button of the
## panel grows by one factor, so the smallest text still reads (ReadableText) and the sizes
## keep their order.

## How much the text is grown now (1 when the design's sizes are readable as they are).
var factor := 1.0

var _designed: Dictionary = {}  # Label or Button -> its font size in the design
var _button_sizes: Dictionary = {}  # Button -> its minimum size in the design


## Reads the font sizes of every label and button under `panel` as designed.
func _init(panel: Control) -> void:
	for node in panel.find_children("*", "Control", true, false):
		var control := node as Control
		if control is Label or control is Button:
			var label := control as Label
			if label != null and label.label_settings != null:
				# a copy: the scene's settings may be shared with other labels
				label.label_settings = label.label_settings.duplicate() as LabelSettings
			_designed[control] = font_size_of(control)
			if control is Button:
				_button_sizes[control] = control.custom_minimum_size


## Grows the text (and the buttons' minimum sizes with it) for a view drawn `screen_scale`
## screen pixels per view unit.
func apply(screen_scale: float) -> void:
	var smallest := 1000
	for size: int in _designed.values():
		smallest = mini(smallest, size)
	factor = ReadableText.growth_at(smallest, screen_scale)
	for control: Control in _designed.keys():
		var designed: int = _designed[control]
		var size := ceili(designed * factor - 0.001)
		var label := control as Label
		if label != null and label.label_settings != null:
			label.label_settings.font_size = size
		else:
			control.add_theme_font_size_override("font_size", size)
	for button: Button in _button_sizes.keys():
		var designed_size: Vector2 = _button_sizes[button]
		button.custom_minimum_size = (designed_size * factor).ceil()


## The controls whose text is kept readable (for tests).
func controls() -> Array:
	return _designed.keys()


## The font size `control` draws with (its label settings' when it has them).
static func font_size_of(control: Control) -> int:
	var label := control as Label
	if label != null and label.label_settings != null:
		return label.label_settings.font_size
	return control.get_theme_font_size(&"font_size")
