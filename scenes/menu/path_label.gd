class_name PathLabel
extends Label
## A label that shows a folder's path after a lead-in ("Folder: …"), trimmed from the
## start when it is too long for the label, so the end of the path (the folder the player is
## looking for) stays in view: "Folder: …/Board Studio/boards/pachinko". The whole path is
## the tooltip.

const ELLIPSIS := "…"

var _lead_in := ""
var _path := ""


func _ready() -> void:
	resized.connect(_fit)
	# a tooltip needs the mouse; the label takes no clicks otherwise
	mouse_filter = Control.MOUSE_FILTER_PASS
	text_overrun_behavior = TextServer.OVERRUN_NO_TRIMMING
	clip_text = true


## Shows `path` after `lead_in`, trimmed from the start to the label's width.
func show_path(lead_in: String, path: String) -> void:
	_lead_in = lead_in
	_path = path
	tooltip_text = path
	_fit()


## The path shown in full (the tooltip's text).
func full_path() -> String:
	return _path


func _fit() -> void:
	text = _lead_in + _path
	var room := size.x
	if room <= 0.0 or _width_of(text) <= room:
		return
	# drop whole folders from the start first, then characters, until it fits
	var parts := _path.split("/")
	for first in range(1, parts.size()):
		text = _lead_in + ELLIPSIS + "/" + "/".join(parts.slice(first))
		if _width_of(text) <= room:
			return
	var tail := parts[parts.size() - 1]
	while tail.length() > 1 and _width_of(_lead_in + ELLIPSIS + tail) > room:
		tail = tail.substr(1)
	text = _lead_in + ELLIPSIS + tail


func _width_of(words: String) -> float:
	var font := get_theme_font(&"font")
	var font_size := get_theme_font_size(&"font_size")
	return font.get_string_size(words, HORIZONTAL_ALIGNMENT_LEFT, -1, font_size).x
