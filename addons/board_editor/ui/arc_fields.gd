@tool
extends VBoxContainer
## The Selection panel's pin arc fields: when the selected pins form an arc (PinArc), its
## centre, radius, start and end angle and pin count, each change one undo step that
## reshapes the arc (EditArcAction) and keeps it selected.

const NumberRow := preload("res://addons/board_editor/ui/number_row.gd")
const BoardEditSession := preload("res://addons/board_editor/board_edit_session.gd")
const PinArc := preload("res://addons/board_editor/core/pin_arc.gd")
const EditArcAction := preload("res://addons/board_editor/actions/edit_arc_action.gd")

## PinArc key -> [label, lowest, highest, step].
const FIELDS := {
	"center_x": ["Centre x (px)", -2000.0, 4000.0, 0.5],
	"center_y": ["Centre y (px)", -2000.0, 4000.0, 0.5],
	"radius": ["Radius (px)", 2.0, 2000.0, 0.5],
	"start_deg": ["Start angle (°)", -720.0, 720.0, 0.5],
	"end_deg": ["End angle (°)", -720.0, 720.0, 0.5],
	"count": ["Pins", 2.0, 400.0, 1.0, true],
}

var _session: BoardEditSession
var _arc: Dictionary = {}
var _fields: Dictionary[String, SpinBox] = {}


func _init() -> void:
	var heading := Label.new()
	heading.text = "Pin arc (0° = right, 90° = down)"
	heading.add_theme_color_override("font_color", Color(1.0, 0.85, 0.3))
	heading.autowrap_mode = TextServer.AUTOWRAP_WORD_SMART
	add_child(heading)
	for key: String in PinArc.KEYS:
		var spec: Array = FIELDS[key]
		var row := NumberRow.make(spec)
		var spin := NumberRow.spin_of(row)
		spin.value_changed.connect(_on_value_changed.bind(key))
		add_child(row)
		_fields[key] = spin


## Edits `session`'s selected arc from now on.
func bind(session: BoardEditSession) -> void:
	_session = session


## Shows `arc` (PinArc.of_selection), or hides the fields for {}.
func show_arc(arc: Dictionary) -> void:
	_arc = arc
	visible = not arc.is_empty()
	for key: String in _fields:
		if arc.has(key):
			var value: float = arc[key]
			_fields[key].set_value_no_signal(value)


## The field for `key` (tests and the screenshot hook type into it).
func field(key: String) -> SpinBox:
	return _fields[key]


func _on_value_changed(value: float, key: String) -> void:
	if _session == null or _arc.is_empty():
		return
	# The other values stay exact (a field shows them rounded to its step).
	var shape := _arc.duplicate()
	if key == "count":
		shape[key] = roundi(value)
	else:
		shape[key] = value
	var pins: PackedInt32Array = _arc["pins"]
	var action := EditArcAction.new(_session.level, pins, shape)
	_session.commit(action)
	_session.select(action.selected)
	show_arc(_session.selected_arc())  # the next field edits the new shape
