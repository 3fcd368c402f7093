@tool
extends VBoxContainer
## The dock's tool settings: the pin pattern (kind, count, spacing, rows, arc radius) and
## the pocket inspector (width, depth, payout). With one pocket selected the pocket fields
## edit that pocket (undoably, its pins re-stamped); otherwise they set the next pocket.

const Session := preload("res://addons/board_editor/board_edit_session.gd")
const PatternAction := preload("res://addons/board_editor/actions/pattern_action.gd")
const EditPocketAction := preload("res://addons/board_editor/actions/edit_pocket_action.gd")

var _session: Session
var _kind: OptionButton
var _fields: Dictionary[String, SpinBox] = {}
var _pocket_title: Label
var _pattern_box: VBoxContainer
var _pocket_box: VBoxContainer


func _init() -> void:
	_pattern_box = _section("Pin pattern")
	_kind = OptionButton.new()
	for kind in PatternAction.KINDS:
		_kind.add_item(str({"lattice": "staggered lattice"}.get(kind, kind)).capitalize())
	_kind.item_selected.connect(_on_pattern_changed)
	_pattern_box.add_child(_kind)
	_add_field(_pattern_box, "count", "Pins", 1, 60, 1)
	_add_field(_pattern_box, "spacing", "Spacing (px)", 2, 200, 0.5)
	_add_field(_pattern_box, "rows", "Rows (lattice)", 1, 40, 1)
	_add_field(_pattern_box, "radius", "Radius (arc, px)", 5, 600, 1)
	_pocket_box = _section("Pocket")
	_pocket_title = Label.new()
	_pocket_box.add_child(_pocket_title)
	_add_field(_pocket_box, "width", "Width (px)", 4, 200, 1)
	_add_field(_pocket_box, "depth", "Depth (px)", 4, 200, 1)
	_add_field(_pocket_box, "payout", "Payout (balls)", 0, 99, 1)


## Shows `session`'s settings and edits them from now on.
func bind(session: Session) -> void:
	_session = session
	refresh()


## Updates the fields from the session and the selected pocket.
func refresh() -> void:
	if _session == null:
		return
	var pachinko := _session.level.is_pachinko()
	_pattern_box.visible = pachinko
	_pocket_box.visible = pachinko
	_kind.select(maxi(PatternAction.KINDS.find(str(_session.pattern["kind"])), 0))
	for key: String in ["count", "spacing", "rows", "radius"]:
		var setting: float = _session.pattern[key]
		_fields[key].set_value_no_signal(setting)
	var index := _session.selected_pocket()
	var width := _session.pocket_width
	var depth := _session.pocket_depth
	var payout := _session.pocket_payout
	if index >= 0:
		var spec: PocketSpec = _session.level.pockets[index]
		width = spec.width
		depth = spec.depth
		payout = spec.payout
		_pocket_title.text = "Selected pocket %d" % (index + 1)
	else:
		_pocket_title.text = "Next pocket placed"
	_fields["width"].set_value_no_signal(width)
	_fields["depth"].set_value_no_signal(depth)
	_fields["payout"].set_value_no_signal(payout)


func _section(title: String) -> VBoxContainer:
	var box := VBoxContainer.new()
	var label := Label.new()
	label.text = title
	label.add_theme_color_override("font_color", Color(0.6, 0.8, 1.0))
	box.add_child(label)
	add_child(box)
	return box


func _add_field(
	box: VBoxContainer, key: String, text: String, low: float, high: float, step: float
) -> void:
	var row := HBoxContainer.new()
	var label := Label.new()
	label.text = text
	label.size_flags_horizontal = Control.SIZE_EXPAND_FILL
	row.add_child(label)
	var spin := SpinBox.new()
	spin.min_value = low
	spin.max_value = high
	spin.step = step
	spin.value_changed.connect(_on_field_changed.bind(key))
	row.add_child(spin)
	_fields[key] = spin
	box.add_child(row)


func _on_pattern_changed(index: int) -> void:
	_session.pattern["kind"] = PatternAction.KINDS[index]
	_session.settings_changed.emit()


func _on_field_changed(value: float, key: String) -> void:
	if _session == null:
		return
	if _session.pattern.has(key):
		if key in ["count", "rows"]:
			_session.pattern[key] = int(value)
		else:
			_session.pattern[key] = value
		_session.settings_changed.emit()
		return
	var width := _fields["width"].value
	var depth := _fields["depth"].value
	var payout := int(_fields["payout"].value)
	var index := _session.selected_pocket()
	if index >= 0:
		_session.commit(EditPocketAction.new(_session.level, index, width, depth, payout))
	else:
		_session.pocket_width = width
		_session.pocket_depth = depth
		_session.pocket_payout = payout
