class_name PortraitZoom
extends Node
## Zooms its parent (a screen's content, laid out full-window) in a portrait window. The
## project stretches a 1280 × 720 design to the window, which on a 720 × 1280 phone draws a
## menu at 0.56: card text came out 7-11 px. In portrait the parent is laid out in
## `1 / zoom` of the view and drawn `zoom` times bigger, so it reflows to the narrower room
## (fewer cards a row) at a readable size. A landscape window gets the full-window layout.

## How much bigger the content is drawn in a portrait window.
@export var zoom := 1.3

var _content: Control = null


func _ready() -> void:
	_content = get_parent() as Control
	if _content == null:
		push_error("PortraitZoom: the parent of %s is not a Control" % get_path())
		return
	get_viewport().size_changed.connect(fit)
	# the content may need more room than it was given until it has reflowed (a grid drops
	# a column when it learns its width): fit again once it needs less
	_content.minimum_size_changed.connect(fit, CONNECT_DEFERRED)
	fit.call_deferred()


## Lays the content out for the window's shape now (the view's size changes call it).
func fit() -> void:
	if _content == null or not is_inside_tree():
		return
	var view := _content.get_viewport_rect().size
	if view.y > view.x:
		_content.set_anchors_preset(Control.PRESET_TOP_LEFT)
		_content.position = Vector2.ZERO
		_content.scale = Vector2.ONE * zoom
		_content.size = view / zoom
	else:
		_content.scale = Vector2.ONE
		_content.set_anchors_and_offsets_preset(Control.PRESET_FULL_RECT)


## How much the content is drawn bigger now (1 in a landscape window).
func zoomed_by() -> float:
	return _content.scale.x if _content != null else 1.0
