@tool
extends VBoxContainer
## The dock's "Selection" panel: exact numbers for the one selected item (ItemProperties),
## each change one undo step; with several items selected, their count.

const Session := preload("res://addons/board_editor/board_edit_session.gd")
const Items := preload("res://addons/board_editor/core/board_items.gd")
const ItemProperties := preload("res://addons/board_editor/core/item_properties.gd")
const ItemNames := preload("res://addons/board_editor/core/item_names.gd")

var _session: Session
var _title: Label
var _rows: Dictionary[String, HBoxContainer] = {}
var _fields: Dictionary[String, SpinBox] = {}


func _init() -> void:
	var heading := Label.new()
	heading.text = "Selection"
	heading.add_theme_color_override("font_color", Color(0.6, 0.8, 1.0))
	add_child(heading)
	_title = Label.new()
	_title.autowrap_mode = TextServer.AUTOWRAP_WORD_SMART
	add_child(_title)
	for key: String in ItemProperties.FIELDS:
		var spec: Array = ItemProperties.FIELDS[key]
		var row := HBoxContainer.new()
		var label := Label.new()
		label.text = spec[0]
		label.size_flags_horizontal = Control.SIZE_EXPAND_FILL
		row.add_child(label)
		var spin := SpinBox.new()
		spin.min_value = spec[1]
		spin.max_value = spec[2]
		spin.step = spec[3]
		spin.custom_minimum_size = Vector2(96, 0)
		spin.value_changed.connect(_on_value_changed.bind(key))
		row.add_child(spin)
		add_child(row)
		_rows[key] = row
		_fields[key] = spin


## Shows `session`'s selection and edits it from now on.
func bind(session: Session) -> void:
	_session = session
	refresh()


## The field for `key` (tests and the screenshot hook type into it).
func field(key: String) -> SpinBox:
	return _fields[key]


## Updates the title and the fields from the selection.
func refresh() -> void:
	var values := {}
	if _session == null or _session.level == null:
		_title.text = ""
	elif _session.selection.size() == 1:
		var item: Vector2i = _session.selection[0]
		values = ItemProperties.values_of(_session.level, item)
		_title.text = ItemNames.title(_session.level, item)
	elif _session.selection.is_empty():
		_title.text = "Nothing selected: click an item with the Select tool (Q)."
	else:
		_title.text = "%d items selected." % _session.selection.size()
	for key: String in _rows:
		_rows[key].visible = values.has(key)
		if values.has(key):
			_fields[key].set_value_no_signal(float(values[key]))


func _on_value_changed(value: float, key: String) -> void:
	if _session == null or _session.selection.size() != 1:
		return
	var item: Vector2i = _session.selection[0]
	var action := ItemProperties.action_for(_session.level, item, key, value)
	if action != null:
		_session.commit(action)
	refresh()
