class_name FrameCounter
extends CanvasLayer
## Frames per second in the top-right corner (or the bottom-left one, for a screen whose
## top right holds its title). Shown when the setting says so; the `toggle_frame_counter`
## action flips the setting (and saves it).

const REFRESH_SECONDS := 0.25
## The widest figure the counter shows: its width is kept whatever the figure, so the panel
## never moves or grows off the screen's edge as the frame rate falls.
const WIDEST_TEXT := "888 FPS  888.8 ms"
## Space kept between the counter and the screen's edge.
const EDGE_MARGIN := 8

## True: the counter sits in the bottom-left corner instead of the top-right one.
@export var bottom_left := false

var _since_refresh := 0.0

@onready var _label: Label = %FpsLabel


func _ready() -> void:
	process_mode = Node.PROCESS_MODE_ALWAYS
	_label.custom_minimum_size.x = _width_of(WIDEST_TEXT)
	if bottom_left:
		_label.set_anchors_and_offsets_preset(
			Control.PRESET_BOTTOM_LEFT, Control.PRESET_MODE_MINSIZE, EDGE_MARGIN
		)
		# from the left edge it grows to the right, never past the edge
		_label.grow_horizontal = Control.GROW_DIRECTION_END
		_label.horizontal_alignment = HORIZONTAL_ALIGNMENT_LEFT
	else:
		_label.set_anchors_and_offsets_preset(
			Control.PRESET_TOP_RIGHT, Control.PRESET_MODE_MINSIZE, EDGE_MARGIN
		)
		_label.grow_horizontal = Control.GROW_DIRECTION_BEGIN
	App.settings.changed.connect(_sync_visibility)
	_sync_visibility()


func _process(delta: float) -> void:
	if not visible:
		return
	_since_refresh += delta
	if _since_refresh >= REFRESH_SECONDS:
		_since_refresh = 0.0
		_refresh()


func _unhandled_input(event: InputEvent) -> void:
	if event.is_action_pressed("toggle_frame_counter"):
		App.settings.set_value("show_frame_counter", not App.settings.show_frame_counter)
		App.save_settings()
		get_viewport().set_input_as_handled()


func _sync_visibility() -> void:
	visible = App.settings.show_frame_counter
	if visible:
		_refresh()


# The label's width for a text: the font's measure and its panel's margins.
func _width_of(text: String) -> float:
	var font := _label.get_theme_font("font")
	var size := _label.get_theme_font_size("font_size")
	var back := _label.get_theme_stylebox("normal")
	return ceilf(
		(
			font.get_string_size(text, HORIZONTAL_ALIGNMENT_LEFT, -1, size).x
			+ back.get_minimum_size().x
		)
	)


func _refresh() -> void:
	var fps := Engine.get_frames_per_second()
	var frame_ms := 1000.0 / fps if fps > 0.0 else 0.0
	_label.text = "%d FPS  %.1f ms" % [fps, frame_ms]
