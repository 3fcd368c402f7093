@tool
extends VBoxContainer
## The dock's tool settings, for the active tool only: the pin pattern (kind, count,
## spacing, rows), the peg curve, and the size and payout of the next pocket placed. (A
## placed pocket is edited in the Selection panel, PropertyPanel.) Only the fields the
## chosen pattern uses are shown.

const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const PatternAction := preload("res://addons/board_editor/actions/pattern_action.gd")

## The pattern fields each kind reads. An arc is placed through three points (its ends and
## a bulge), so it takes the pin count only; its old radius field did nothing any more.
const PATTERN_FIELDS: Dictionary[String, Array] = {
	"row": ["count", "spacing"],
	"lattice": ["count", "spacing", "rows"],
	"arc": ["count"],
	"circle": ["count", "spacing"],
}

var _session: BoardEditSession
var _kind: OptionButton
var _fields: Dictionary[String, SpinBox] = {}
var _pattern_box: VBoxContainer
var _curve_box: VBoxContainer
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
	_add_field(_pattern_box, "rows", "Rows", 1, 40, 1)
	_curve_box = _section("Peg curve (C)")
	_add_field(_curve_box, "curve_count", "Pins (0: by spacing)", 0, 200, 1)
	_add_field(_curve_box, "curve_spacing", "Spacing (px)", 4, 200, 0.5)
	_pocket_box = _section("Next pocket placed")
	_add_field(_pocket_box, "width", "Width (px)", 4, 200, 1)
	_add_field(_pocket_box, "depth", "Depth (px)", 4, 200, 1)
	_add_field(_pocket_box, "payout", "Payout (balls)", 0, 99, 1)


## Shows `session`'s settings and edits them from now on.
func bind(session: BoardEditSession) -> void:
	_session = session
	if session != null and not session.tool_changed.is_connected(_on_tool_changed):
		session.tool_changed.connect(_on_tool_changed)
	refresh()


## Whether the pattern field `key` ("count", "spacing", "rows") is on show.
func shows_pattern_field(key: String) -> bool:
	return _fields.has(key) and (_fields[key].get_parent() as Control).visible


## Updates the fields from the session and the selected pocket.
func refresh() -> void:
	if _session == null:
		return
	# Only the active tool's settings: the dock keeps its height for the Selection panel and
	# the analysis.
	var pachinko := _session.level.is_pachinko()
	_pattern_box.visible = pachinko and _session.tool == BoardEditSession.Tool.PATTERN
	_curve_box.visible = pachinko and _session.tool == BoardEditSession.Tool.CURVE
	var curve_count: int = _session.curve["count"]
	var curve_spacing: float = _session.curve["spacing"]
	_fields["curve_count"].set_value_no_signal(curve_count)
	_fields["curve_spacing"].set_value_no_signal(curve_spacing)
	_pocket_box.visible = pachinko and _session.tool == BoardEditSession.Tool.POCKET
	_kind.select(maxi(PatternAction.KINDS.find(str(_session.pattern["kind"])), 0))
	var used: Array = PATTERN_FIELDS.get(str(_session.pattern["kind"]), [])
	for key: String in ["count", "spacing", "rows"]:
		var setting: float = _session.pattern[key]
		_fields[key].set_value_no_signal(setting)
		(_fields[key].get_parent() as Control).visible = used.has(key)
	_fields["width"].set_value_no_signal(_session.pocket_width)
	_fields["depth"].set_value_no_signal(_session.pocket_depth)
	_fields["payout"].set_value_no_signal(_session.pocket_payout)


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


func _on_tool_changed(_tool: int) -> void:
	refresh()


func _on_pattern_changed(index: int) -> void:
	_session.pattern["kind"] = PatternAction.KINDS[index]
	_session.settings_changed.emit()
	refresh()


func _on_field_changed(value: float, key: String) -> void:
	if _session == null:
		return
	if key.begins_with("curve_"):
		var setting := key.trim_prefix("curve_")
		if setting == "count":
			_session.curve[setting] = int(value)
		else:
			_session.curve[setting] = value
		_session.settings_changed.emit()
		return
	if _session.pattern.has(key):
		if key in ["count", "rows"]:
			_session.pattern[key] = int(value)
		else:
			_session.pattern[key] = value
		_session.settings_changed.emit()
		return
	_session.pocket_width = _fields["width"].value
	_session.pocket_depth = _fields["depth"].value
	_session.pocket_payout = int(_fields["payout"].value)
