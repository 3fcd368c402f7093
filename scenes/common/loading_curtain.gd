class_name LoadingCurtain
extends CanvasLayer
## The sign of life while a screen loads: a dimmed window with "Loading…" and a turning ring,
## over everything, raised the moment a scene change is asked for and lowered once the new
## screen has drawn its first frame. It takes the clicks made meanwhile (an impatient click
## must not land on the new screen). The App owns the one curtain; `cover()` and `lift()`
## are all there is. The ring turns whenever the main thread gets a frame in.

## Above every screen's own layers (the pause menu is 10, the frame counter 20).
const LAYER := 90
const DIM := Color(0.02, 0.01, 0.05, 0.55)
const TEXT_COLOR := Color(1.0, 0.86, 0.5)
const CARD_COLOR := Color(0.086, 0.055, 0.16, 0.96)
const FONT_SIZE := 28
## Turns per second of the ring.
const SPIN := 1.2

var _shade: Control
var _label: Label
var _ring: Control
var _angle := 0.0


func _init() -> void:
	layer = LAYER
	visible = false
	_shade = ColorRect.new()
	(_shade as ColorRect).color = DIM
	_shade.set_anchors_preset(Control.PRESET_FULL_RECT)
	_shade.mouse_filter = Control.MOUSE_FILTER_STOP
	add_child(_shade)
	var centre := CenterContainer.new()
	centre.set_anchors_preset(Control.PRESET_FULL_RECT)
	centre.mouse_filter = Control.MOUSE_FILTER_IGNORE
	_shade.add_child(centre)
	# a dark card of its own, so the words read over any screen
	var card := PanelContainer.new()
	var style := StyleBoxFlat.new()
	style.bg_color = CARD_COLOR
	style.border_color = Color(TEXT_COLOR, 0.6)
	style.set_border_width_all(2)
	style.set_corner_radius_all(14)
	style.set_content_margin_all(22)
	style.content_margin_left = 40
	style.content_margin_right = 40
	card.add_theme_stylebox_override(&"panel", style)
	card.mouse_filter = Control.MOUSE_FILTER_IGNORE
	centre.add_child(card)
	var column := VBoxContainer.new()
	column.alignment = BoxContainer.ALIGNMENT_CENTER
	column.mouse_filter = Control.MOUSE_FILTER_IGNORE
	column.add_theme_constant_override(&"separation", 14)
	card.add_child(column)
	_ring = Control.new()
	_ring.custom_minimum_size = Vector2(56, 56)
	_ring.size_flags_horizontal = Control.SIZE_SHRINK_CENTER
	_ring.mouse_filter = Control.MOUSE_FILTER_IGNORE
	_ring.draw.connect(_draw_ring)
	column.add_child(_ring)
	_label = Label.new()
	_label.text = "Loading…"
	_label.horizontal_alignment = HORIZONTAL_ALIGNMENT_CENTER
	_label.add_theme_font_size_override(&"font_size", FONT_SIZE)
	_label.add_theme_color_override(&"font_color", TEXT_COLOR)
	_label.add_theme_constant_override(&"outline_size", 6)
	_label.add_theme_color_override(&"font_outline_color", Color(0.05, 0.02, 0.1))
	column.add_child(_label)
	set_process(false)


## True while the curtain is up.
func is_covering() -> bool:
	return visible


## The words under the ring.
func words() -> String:
	return _label.text


## Raises the curtain at once with `text` under the turning ring.
func cover(text: String = "Loading…") -> void:
	_label.text = text
	visible = true
	set_process(true)


## Lowers the curtain.
func lift() -> void:
	visible = false
	set_process(false)


func _process(delta: float) -> void:
	_angle = wrapf(_angle + delta * SPIN * TAU, 0.0, TAU)
	_ring.queue_redraw()


func _draw_ring() -> void:
	var centre := _ring.size * 0.5
	var radius := minf(centre.x, centre.y) - 4.0
	_ring.draw_arc(centre, radius, 0.0, TAU, 48, Color(TEXT_COLOR, 0.2), 6.0, true)
	_ring.draw_arc(centre, radius, _angle, _angle + TAU * 0.3, 24, TEXT_COLOR, 6.0, true)
