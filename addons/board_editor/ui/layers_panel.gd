@tool
extends VBoxContainer
## The dock's layers: per layer of the board (Layers), a Show box and a Lock box. Hidden
## layers are not drawn and cannot be picked; locked ones are drawn but cannot be picked.

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const Layers := preload("res://addons/board_editor/core/layers.gd")

var _session: BoardEditSession
var _grid: GridContainer


func _init() -> void:
	var heading := Label.new()
	heading.text = "Layers"
	heading.add_theme_color_override("font_color", Color(0.6, 0.8, 1.0))
	add_child(heading)
	_grid = GridContainer.new()
	_grid.columns = 3
	add_child(_grid)


## Shows `session`'s layers and edits them from now on.
func bind(session: BoardEditSession) -> void:
	if _session == session:
		refresh()
		return
	_session = session
	for child in _grid.get_children():
		_grid.remove_child(child)
		child.queue_free()
	if session == null:
		return
	for layer in Layers.for_kind(session.level.kind):
		var name_label := Label.new()
		name_label.text = layer
		name_label.size_flags_horizontal = Control.SIZE_EXPAND_FILL
		_grid.add_child(name_label)
		var what := layer.to_lower()
		_grid.add_child(_box("Show", "Draw the %s; hidden ones cannot be picked." % what, layer))
		_grid.add_child(
			_box("Lock", "Keep the %s from being picked, moved or erased." % what, layer)
		)
	refresh()


## Updates the boxes from the session.
func refresh() -> void:
	if _session == null:
		return
	for child in _grid.get_children():
		if child is CheckBox:
			var box := child as CheckBox
			var layer: String = box.get_meta("layer")
			var on := _session.locked_layers.has(layer)
			if box.text == "Show":
				on = not _session.hidden_layers.has(layer)
			box.set_pressed_no_signal(on)


## Hides (or shows) a layer, as the Show box does.
func set_hidden(layer: String, hide_layer: bool) -> void:
	_session.set_layer(layer, hide_layer, _session.locked_layers.has(layer))


func _box(text: String, tooltip: String, layer: String) -> CheckBox:
	var box := CheckBox.new()
	box.text = text
	box.tooltip_text = tooltip
	box.focus_mode = Control.FOCUS_NONE
	box.set_meta("layer", layer)
	box.toggled.connect(
		func(on: bool) -> void:
			if text == "Show":
				set_hidden(layer, not on)
			else:
				_session.set_layer(layer, _session.hidden_layers.has(layer), on)
	)
	return box
