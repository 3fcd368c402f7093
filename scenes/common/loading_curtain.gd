class_name LoadingCurtain
extends CanvasLayer
## The sign of life while a screen loads: a dimmed window with "Loading…" and a turning ring,
## over everything, raised the moment a scene change is asked for and lowered once the new
## screen has drawn its first frame. It takes the clicks made meanwhile (an impatient click
## must not land on the new screen). The App owns the one curtain and calls `cover()` and
## `lift()`; a new screen that draws itself over several frames (the maze compiles its 3D
## shaders one part a frame) keeps it up meanwhile with `hold_until()`. The ring turns
## whenever the main thread gets a frame in.

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
# a screen still drawing itself keeps the curtain up: a lift asked for meanwhile waits
var _held := false
var _lift_waiting := false
# holds asked for so far: only the latest one's end counts
var _holds := 0


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


## True while a screen keeps the curtain up (`hold_until`).
func is_held() -> bool:
	return _held


## Raises the curtain at once with `text` under the turning ring (forgetting any hold: a new
## screen is on its way).
func cover(text: String = "Loading…") -> void:
	_label.text = text
	_held = false
	_lift_waiting = false
	visible = true
	set_process(true)


## Lowers the curtain, or once the hold ends when a screen holds it.
func lift() -> void:
	if _held:
		_lift_waiting = true
		return
	visible = false
	set_process(false)


## Keeps the curtain up, with its ring turning, until `done` is emitted or `holder` leaves
## the tree (a screen freed early must not leave it up); a `lift()` asked for meanwhile
## happens then. Call it from the new screen's _ready, before the App lifts the curtain.
func hold_until(done: Signal, holder: Node) -> void:
	_held = true
	_holds += 1
	var hold := _holds
	var ends := func() -> void: _end_hold(hold)
	done.connect(ends, CONNECT_ONE_SHOT)
	holder.tree_exiting.connect(ends, CONNECT_ONE_SHOT)


# Ends hold number `hold` (the later of its two ends, or an older hold's, finds it over).
func _end_hold(hold: int) -> void:
	if not _held or hold != _holds:
		return
	_held = false
	if _lift_waiting:
		_lift_waiting = false
		lift()


func _process(delta: float) -> void:
	_angle = wrapf(_angle + delta * SPIN * TAU, 0.0, TAU)
	_ring.queue_redraw()


func _draw_ring() -> void:
	var centre := _ring.size * 0.5
	var radius := minf(centre.x, centre.y) - 4.0
	_ring.draw_arc(centre, radius, 0.0, TAU, 48, Color(TEXT_COLOR, 0.2), 6.0, true)
	_ring.draw_arc(centre, radius, _angle, _angle + TAU * 0.3, 24, TEXT_COLOR, 6.0, true)
